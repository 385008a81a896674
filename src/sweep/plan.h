/* Which runs a sweep makes: every combination of the --vary values (grid) or R
 * Latin-hypercube samples (lhs:R), as a table of points (docs/cli.md, reelsim sweep). */
#ifndef RS_SWEEP_PLAN_H
#define RS_SWEEP_PLAN_H

#include <stddef.h>

#include "reelsim/reel.h"
#include "reelsim/status.h"
#include "sweep/vary.h"

/* The Latin hypercube's seed (splitmix64): fixed, so the same command makes the same runs. */
#define SWEEP_LHS_SEED 18ULL
/* At most this many runs in one sweep. */
enum { SWEEP_MAX_RUNS = 10000000 };

typedef enum sweep_sample_kind { SWEEP_SAMPLE_GRID, SWEEP_SAMPLE_LHS } sweep_sample_kind;

typedef struct sweep_sample {
  sweep_sample_kind kind;
  int runs; /* lhs: R */
} sweep_sample;

/* "grid" or "lhs:R" (R >= 1). RS_ERR_INPUT "--sample ARG: why". */
rs_status sweep_sample_parse(const char *arg, sweep_sample *s);
/* "grid" or "lhs:R" into buf. */
void sweep_sample_name(const sweep_sample *s, char *buf, size_t size);

/* The forms of --vary a sample takes: grid needs values (LO:HI:N or a list); lhs takes a
 * range (LO:HI, or LO:HI:N whose N it does not use) or a list. */
unsigned sweep_sample_vary_forms(const sweep_sample *s);

typedef struct sweep_plan {
  int n_keys;
  const sweep_vary *vary; /* the keys (not owned) */
  int n_runs;
  double *points;         /* n_runs x n_keys, row-major: the value, or a word's index */
} sweep_plan;

/* grid: every combination, the first key varying slowest (as nested loops in the order of
 * the --vary arguments). lhs:R: each key's range [LO, HI] cut into R equal strata, one
 * uniform sample in each, the strata of each key in their own random order (splitmix64
 * seeded with SWEEP_LHS_SEED, the keys drawn in the order given); a list's item for
 * stratum j is item floor(j n / R). RS_ERR_INPUT when the grid has more than
 * SWEEP_MAX_RUNS runs. */
rs_status sweep_plan_make(int n_keys, const sweep_vary *vary, const sweep_sample *s,
                          sweep_plan *plan);
/* The same, asking stop(NULL, 0, 0) every 65536 points (a plan of 10^7 runs takes seconds
 * to make): nonzero gives RS_ERR_INTERRUPTED and no plan. stop may be NULL. */
rs_status sweep_plan_make_stoppable(int n_keys, const sweep_vary *vary, const sweep_sample *s,
                                    rs_reel_progress_fn stop, sweep_plan *plan);
void sweep_plan_free(sweep_plan *plan);

/* The overrides of run i: sets[0..n_sets) then "KEY=VALUE" for every key, into *all
 * (n_sets + n_keys pointers, malloc'd) and *text (their storage, malloc'd). Free both. */
rs_status sweep_plan_sets(const sweep_plan *plan, int i, int n_sets, const char *const *sets,
                          const char ***all, char **text);

/* The plan's size alone (a grid's product of counts; lhs:R was bounded when parsed),
 * checked before any scene is loaded: RS_ERR_INPUT beyond SWEEP_MAX_RUNS. */
rs_status sweep_plan_check_size(int n_keys, const sweep_vary *vary, const sweep_sample *s);

#endif
