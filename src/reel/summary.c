/* Whether a summary can be shown: NaN or Inf in a figure means a broken solution. */
#include <math.h>
#include <stddef.h>

#include "reelsim/reel.h"

int rs_reel_summary_finite(const rs_reel_summary *s, const char **what)
{
  const struct {
    const char *name;
    double v;
  } f[] = {
      {"final radius", s->final_radius},
      {"core pressure", s->core_pressure},
      {"peak pressure", s->peak_pressure},
      {"radius of the peak pressure", s->peak_pressure_radius},
      {"minimum hoop stress", s->min_hoop},
      {"radius of the minimum hoop stress", s->min_hoop_radius},
      {"least wound-on tension", s->wot_min},
      {"greatest wound-on tension", s->wot_max},
  };
  for (size_t i = 0; i < sizeof f / sizeof f[0]; ++i)
    if (!isfinite(f[i].v)) {
      if (what) *what = f[i].name;
      return 0;
    }
  return 1;
}
