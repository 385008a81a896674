/* Saving and restoring a roll's stresses (the reel's adaptive nip policy rewinds). */
#include <stdlib.h>
#include <string.h>

#include "roll/roll_internal.h"
#include "util/error.h"

/* ---- save / restore ------------------------------------------------------------------- */

struct rs_roll_state {
  int n, capacity;
  double core_sigma;
  double *sigma_r, *sigma_theta;
};

rs_status rs_roll_state_create(rs_roll_state **out)
{
  *out = calloc(1, sizeof **out);
  return *out ? RS_OK : RS_ERROR(RS_ERR_MEMORY, "cannot allocate a roll state");
}

void rs_roll_state_destroy(rs_roll_state **state)
{
  if (!state || !*state) return;
  free((*state)->sigma_r);
  free((*state)->sigma_theta);
  free(*state);
  *state = NULL;
}

rs_status rs_roll_save(const rs_roll *roll, rs_roll_state *st)
{
  if (st->capacity < roll->n || !st->sigma_r) { /* also before the first layer: memcpy needs arrays */
    int cap = roll->p.max_layers;
    double *a = realloc(st->sigma_r, (size_t)cap * sizeof(double));
    if (a) st->sigma_r = a;
    double *b = realloc(st->sigma_theta, (size_t)cap * sizeof(double));
    if (b) st->sigma_theta = b;
    if (!a || !b) return RS_ERROR(RS_ERR_MEMORY, "cannot save a roll of %d layers", roll->n);
    st->capacity = cap;
  }
  st->n = roll->n;
  st->core_sigma = -rs_roll_core_pressure(roll); /* the lazy deep part applied */
  if (roll->n > 0) { /* an empty roll has no arrays yet: memcpy of NULL is undefined */
    memcpy(st->sigma_r, rs_roll_sigma_r(roll), (size_t)roll->n * sizeof(double));
    memcpy(st->sigma_theta, rs_roll_sigma_theta(roll), (size_t)roll->n * sizeof(double));
  }
  return RS_OK;
}

rs_status rs_roll_restore(rs_roll *roll, const rs_roll_state *st)
{
  if (st->n > roll->p.max_layers)
    return RS_ERROR(RS_ERR_INTERNAL, "a state of %d layers does not fit a roll of %d", st->n,
                    roll->p.max_layers);
  roll->n = st->n;
  rsi_roll_lazy_clear(roll);          /* the state holds the stresses in full */
  rsi_roll_profile_drop(roll);        /* the reference's profile no longer applies */
  rsi_roll_reference_restored(roll);  /* nor the starts of the roll wound since */
  roll->core_sigma = st->core_sigma; /* the work counters keep counting: rewinding costs */
  if (st->n > 0) { /* the state of an empty roll has no arrays */
    memcpy(roll->sigma_r, st->sigma_r, (size_t)st->n * sizeof(double));
    memcpy(roll->sigma_theta, st->sigma_theta, (size_t)st->n * sizeof(double));
    roll->hoop_stale = 0;
  }
  return RS_OK;
}
