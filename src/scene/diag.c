/* Locating range-check errors (a dotted scene path -> the node the user wrote), and
 * collecting every error of one load so that they are reported together. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "scene/scene_internal.h"
#include "util/error.h"

int rsi_ys_has(const yn *root, const char *path) { return rsi_yn_get(root, path) != NULL; }

rs_status rsi_ys_fail(const yn *root, const char *path, const char *fmt, ...)
{
  char msg[1536], trimmed[1024];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);

  const yn *node = rsi_yn_get(root, path);
  if (node) return rsi_yn_error(node, "%s", msg);
  /* absent key: report at the nearest parent that is there, under the full key name */
  snprintf(trimmed, sizeof trimmed, "%s", path);
  for (;;) {
    char *cut = strrchr(trimmed, '.');
    char *br = strrchr(trimmed, '[');
    if (br && (!cut || br > cut)) cut = br;
    if (!cut) {
      node = root;
      break;
    }
    *cut = '\0';
    node = rsi_yn_get(root, trimmed);
    if (node) break;
  }
  const char *rest = path + strlen(trimmed);
  if (*rest == '.') ++rest;
  return rsi_yn_error_key(node, rest, "%s", msg);
}

/* %g without the exponent's plus sign and leading zeros: 1e9, 7e-5, 0.19. */
void rsi_ys_fmt(char *buf, size_t size, double v)
{
  char tmp[64];
  snprintf(tmp, sizeof tmp, "%g", v);
  char *e = strchr(tmp, 'e');
  if (!e) {
    snprintf(buf, size, "%s", tmp);
    return;
  }
  char mant[64];
  snprintf(mant, sizeof mant, "%.*s", (int)(e - tmp), tmp);
  const char *x = e + 1;
  int neg = *x == '-';
  if (*x == '+' || *x == '-') ++x;
  while (*x == '0' && x[1]) ++x;
  snprintf(buf, size, "%se%s%s", mant, neg ? "-" : "", x);
}

/* The errors of the load in progress on this thread (loads on other threads are their own). */
enum { YS_ERRORS_TEXT = 8192 };
static _Thread_local struct {
  int n;                      /* errors noted */
  size_t len;
  char text[YS_ERRORS_TEXT];  /* the first YS_MAX_ERRORS, one a line */
} errs;

void rsi_ys_errors_begin(void)
{
  errs.n = 0;
  errs.len = 0;
  errs.text[0] = '\0';
}

rs_status rsi_ys_note(rs_status st)
{
  if (st != RS_ERR_INPUT) return st;
  if (errs.n++ < YS_MAX_ERRORS) {
    int w = snprintf(errs.text + errs.len, sizeof errs.text - errs.len, "%s%s",
                     errs.len ? "\n" : "", rs_error_message());
    if (w > 0) errs.len = (size_t)w < sizeof errs.text - errs.len ? errs.len + (size_t)w
                                                                   : sizeof errs.text - 1;
  }
  return st;
}

int rsi_ys_errors(void) { return errs.n; }

rs_status rsi_ys_errors_end(void)
{
  if (errs.n == 0) return RS_OK;
  if (errs.n == 1) return RS_ERROR(RS_ERR_INPUT, "%s", errs.text);
  if (errs.n > YS_MAX_ERRORS)
    return RS_ERROR(RS_ERR_INPUT, "%s\n(%d more errors not shown; %d in all)", errs.text,
                    errs.n - YS_MAX_ERRORS, errs.n);
  return RS_ERROR(RS_ERR_INPUT, "%s", errs.text);
}
