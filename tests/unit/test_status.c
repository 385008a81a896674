/* The error record: what a failure records is what the caller reads back. */
#include "check.h"
#include "reelsim/status.h"
#include "util/error.h"

static rs_status fail_deep(void) { return RS_ERROR(RS_ERR_SOLVER, "no convergence after %d tries", 7); }

static void set_and_wrap(void)
{
  rs_error_clear();
  CHECK(rs_error_status() == RS_OK);
  rs_status st = fail_deep();
  CHECK(st == RS_ERR_SOLVER);
  CHECK(strcmp(rs_error_message(), "no convergence after 7 tries") == 0);
  CHECK(strstr(rs_error_where(), "fail_deep") != NULL);
  CHECK(rs_error_wrap("layer %d", 12) == RS_ERR_SOLVER);
  CHECK(strcmp(rs_error_message(), "layer 12: no convergence after 7 tries") == 0);
  rs_error_clear();
  CHECK(rs_error_message()[0] == '\0');
}

static void exit_codes(void)
{
  CHECK(rs_status_exit_code(RS_OK) == 0);
  CHECK(rs_status_exit_code(RS_ERR_INPUT) == 2);
  CHECK(rs_status_exit_code(RS_ERR_SOLVER) == 3);
  CHECK(rs_status_exit_code(RS_ERR_IO) == 1);
  CHECK(rs_status_exit_code(RS_ERR_INTERNAL) == 1);
}

static const check_case cases[] = {{"set_and_wrap", set_and_wrap}, {"exit_codes", exit_codes}};
int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
