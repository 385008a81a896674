/* A small check harness for plain ctest executables.
 *
 * A test program defines its cases and hands them to check_main():
 *
 *   static void altmann_rigid(void) { CHECK_CLOSE(p, p_exact, 1e-6); }
 *   static const check_case cases[] = { {"altmann_rigid", altmann_rigid}, ... };
 *   int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
 *
 * ctest runs one entry per case (`exe altmann_rigid`); without an argument every case
 * runs. Values print to 17 significant digits so a failure shows what really differed.
 * A case that runs no check fails: it could not have caught anything. */
#ifndef RS_TESTS_CHECK_H
#define RS_TESTS_CHECK_H

#include <math.h>
#include <stdio.h>
#include <string.h>

typedef struct check_case {
  const char *name;
  void (*fn)(void);
} check_case;

static int check_failures = 0;
static int check_count = 0;

#define CHECK(cond)                                                                    \
  do {                                                                                 \
    ++check_count;                                                                     \
    if (!(cond)) {                                                                     \
      ++check_failures;                                                                \
      fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond);         \
    }                                                                                  \
  } while (0)

/* |a - b| <= rtol * |b| (b is the expected value). */
#define CHECK_CLOSE(a, b, rtol) check_close_((a), (b), (rtol), 0.0, #a, #b, __FILE__, __LINE__)
/* |a - b| <= atol */
#define CHECK_ABS(a, b, atol) check_close_((a), (b), 0.0, (atol), #a, #b, __FILE__, __LINE__)
/* a < b, printing both */
#define CHECK_LT(a, b) check_lt_((a), (b), #a, #b, __FILE__, __LINE__)
#define CHECK_FINITE(a) check_lt_(fabs(a), INFINITY, "|" #a "|", "inf", __FILE__, __LINE__)

static inline void check_close_(double a, double b, double rtol, double atol, const char *ea,
                                const char *eb, const char *file, int line)
{
  double tol = atol + rtol * fabs(b);
  ++check_count;
  if (!(fabs(a - b) <= tol)) {
    ++check_failures;
    fprintf(stderr,
            "%s:%d: CHECK_CLOSE failed\n  %s = %.17g\n  %s = %.17g\n  |diff| = %.17g, "
            "rel = %.17g, tol = %.17g\n",
            file, line, ea, a, eb, b, fabs(a - b), b != 0 ? fabs(a - b) / fabs(b) : fabs(a - b),
            tol);
  }
}

static inline void check_lt_(double a, double b, const char *ea, const char *eb, const char *file,
                             int line)
{
  ++check_count;
  if (!(a < b)) {
    ++check_failures;
    fprintf(stderr, "%s:%d: CHECK_LT failed\n  %s = %.17g\n  %s = %.17g\n", file, line, ea, a, eb,
            b);
  }
}

/* Print a labelled value to 17 digits (for convergence tables in the test log). */
#define CHECK_LOG(label, value) printf("  %-40s %.17g\n", (label), (double)(value))

static inline int check_main_(int argc, char **argv, const check_case *cases, size_t n)
{
  int ran = 0;
  for (size_t i = 0; i < n; ++i) {
    if (argc > 1 && strcmp(argv[1], cases[i].name) != 0) continue;
    int before = check_failures, counted = check_count;
    printf("case %s\n", cases[i].name);
    fflush(stdout);
    cases[i].fn();
    if (check_count == counted) {
      ++check_failures;
      fprintf(stderr, "case %s ran no check: a test that checks nothing cannot fail\n",
              cases[i].name);
    }
    printf("case %s: %s\n", cases[i].name, check_failures == before ? "ok" : "FAILED");
    ++ran;
  }
  if (ran == 0) {
    fprintf(stderr, "no case named '%s'\n", argc > 1 ? argv[1] : "");
    return 2;
  }
  printf("%d checks, %d failed\n", check_count, check_failures);
  return check_failures ? 1 : 0;
}

#define CHECK_MAIN(argc, argv, cases) \
  check_main_((argc), (argv), (cases), sizeof(cases) / sizeof((cases)[0]))

#endif
