/* What a recipe search varies: `--vary KEY=...` arguments (reelsim sweep, reelsim optimize).
 *
 *   KEY=LO:HI:N     N values evenly spaced from LO to HI (N >= 1; N = 1 is LO alone)
 *   KEY=LO:HI       a range with no count (optimize searches inside it)
 *   KEY=V1,V2,...   a list: numbers, or words when any item is not a number
 *
 * One parser for both commands; `allowed` says which forms a command takes. KEY is a scene
 * key path (docs/scenes.md) that --set would take: sweep_vary_check loads the scene with
 * the values to find out. Part of the recipe-search application layer (src/sweep): it uses
 * only the public headers. */
#ifndef RS_SWEEP_VARY_H
#define RS_SWEEP_VARY_H

#include <stddef.h>

#include "reelsim/reel.h"
#include "reelsim/status.h"

/* The forms a command accepts (a bit set). */
enum {
  SWEEP_VARY_GRID = 1u << 0,  /* KEY=LO:HI:N */
  SWEEP_VARY_RANGE = 1u << 1, /* KEY=LO:HI */
  SWEEP_VARY_LIST = 1u << 2   /* KEY=V1,V2,... */
};

typedef enum sweep_vary_kind { SWEEP_GRID, SWEEP_RANGE, SWEEP_LIST } sweep_vary_kind;

enum { SWEEP_KEY_MAX = 128 };

typedef struct sweep_vary {
  const char *arg;          /* the argument as given ("winding.tension=200:400:5"), for messages */
  char key[SWEEP_KEY_MAX];  /* "winding.tension" */
  sweep_vary_kind kind;
  double lo, hi;            /* GRID, RANGE; a numeric LIST: its least and greatest item */
  int n;                    /* GRID: N; LIST: the items; RANGE: 0 */
  double *values;           /* GRID and numeric LIST: the n values (NULL for words, RANGE) */
  char **words;             /* a LIST of words: the n items (NULL otherwise) */
  char *words_text;         /* storage of words[] */
} sweep_vary;

/* Parses one --vary argument (`arg` must outlive *v) into *v. RS_ERR_INPUT, recorded as
 * "--vary ARG: why", for a malformed argument, a form not in `allowed`, LO > HI, N < 1, a
 * value that is not a finite number. Release with sweep_vary_clear (also after a failure). */
rs_status sweep_vary_parse(const char *arg, unsigned allowed, sweep_vary *v);
void sweep_vary_clear(sweep_vary *v);

/* 1 when the values are words (a LIST of words): a point then holds an index into words. */
int sweep_vary_is_words(const sweep_vary *v);

/* The value of the parameter at a point x: a number for numeric keys (any x for RANGE; a
 * GRID or numeric LIST point is values[i]) or the index of a word. Writes the --set text
 * "KEY=VALUE" (numbers as %.17g: the value the scene reads is x exactly). RS_ERR_INPUT when
 * it does not fit in buf or a word index is out of range. */
rs_status sweep_vary_set_text(const sweep_vary *v, double x, char *buf, size_t size);

/* Loads the scene with `sets` alone (its own error is returned as it is), then with `sets`
 * and KEY=value at every value of v a run could use: each item of a LIST and GRID, LO and
 * HI of a RANGE. RS_ERR_INPUT as "--vary ARG: <the scene's message>" when one is refused
 * (an unknown key, a value the key does not take). */
rs_status sweep_vary_check(const char *scene_path, int n_sets, const char *const *sets,
                           const sweep_vary *v);
/* The same, asking stop(NULL, 0, 0) before each value (a grid key may have 10^7):
 * nonzero gives RS_ERR_INTERRUPTED. stop may be NULL. */
rs_status sweep_vary_check_stoppable(const char *scene_path, int n_sets, const char *const *sets,
                                     const sweep_vary *v, rs_reel_progress_fn stop);

#endif
