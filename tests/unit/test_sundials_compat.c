/* src/util/sundials_compat.[ch]: what differs between SUNDIALS 6.4 and 7.x behind one
 * interface. CVODE's error messages reach the buffer in the same form with either
 * ("<module> <function> (code <n>): <message>"), and a context prints nothing. */
#include <string.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>

#include "check.h"
#include "util/sundials_compat.h"

static int rhs(sunrealtype t, N_Vector y, N_Vector f, void *user)
{
  (void)t;
  (void)user;
  N_VScale(-1.0, y, f);
  return 0;
}

/* CVodeInit without a state vector: CVODE refuses with CV_ILL_INPUT (-22) and says why */
static void cvode_error_recorded(void)
{
  SUNContext ctx = NULL;
  CHECK(rs_sundials_context_create(&ctx) == 0);
  if (!ctx) return;
  void *cv = CVodeCreate(CV_BDF, ctx);
  char msg[RS_SUNDIALS_MSG_LEN] = "";
  CHECK(cv && rs_sundials_cvode_messages(cv, ctx, &msg) == 0);
  CHECK(CVodeInit(cv, rhs, 0.0, NULL) == CV_ILL_INPUT);
  printf("  message: %s\n", msg);
  CHECK(strncmp(msg, "CVODE CVodeInit (code -22): ", 28) == 0);
  CHECK(strlen(msg) > 28);
  /* a later error replaces it */
  N_Vector y = N_VNew_Serial(1, ctx);
  CHECK(y != NULL);
  N_VConst(1.0, y);
  CHECK(CVodeInit(cv, rhs, 0.0, y) == CV_SUCCESS);
  CHECK(CVodeSStolerances(cv, -1.0, 0.0) == CV_ILL_INPUT);
  printf("  message: %s\n", msg);
  CHECK(strncmp(msg, "CVODE CVodeSStolerances (code -22): ", 36) == 0);
  CVodeFree(&cv);
  N_VDestroy(y);
  SUNContext_Free(&ctx);
}

static const check_case cases[] = {{"cvode_error_recorded", cvode_error_recorded}};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
