/* The check harness itself (tests/check.h): a case that runs no check fails and says why
 * (tests/cli/harness.cmake runs `test_harness no_check` and expects exit 1 and the
 * message); a case with a passing check passes. */
#include "check.h"

static void no_check(void) {}

static void one_check(void) { CHECK(1 + 1 == 2); }

static const check_case cases[] = {
    {"no_check", no_check},
    {"one_check", one_check},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
