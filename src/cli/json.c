/* The JSON writer (json.h). */
#include "cli/json.h"

#include <math.h>
#include <stdlib.h>

/* 0 when s[0..] does not start a well-formed UTF-8 sequence, else its length */
static int utf8_len(const unsigned char *s)
{
  int n;
  unsigned lo = 0x80, hi = 0xBF;
  if (s[0] < 0x80) return 1;
  if (s[0] >= 0xC2 && s[0] <= 0xDF) n = 2;
  else if (s[0] >= 0xE0 && s[0] <= 0xEF) n = 3;
  else if (s[0] >= 0xF0 && s[0] <= 0xF4) n = 4;
  else return 0;
  /* no overlong forms, no surrogates, nothing beyond U+10FFFF */
  if (s[0] == 0xE0) lo = 0xA0;
  if (s[0] == 0xED) hi = 0x9F;
  if (s[0] == 0xF0) lo = 0x90;
  if (s[0] == 0xF4) hi = 0x8F;
  if (s[1] < lo || s[1] > hi) return 0;
  for (int i = 2; i < n; ++i)
    if (s[i] < 0x80 || s[i] > 0xBF) return 0;
  return n;
}

void cli_json_quote(FILE *out, const char *s)
{
  const unsigned char *p = (const unsigned char *)s;
  fputc('"', out);
  while (*p) {
    unsigned char c = *p;
    int n = utf8_len(p);
    if (n == 0) {
      fputs("\\ufffd", out);
      ++p;
      continue;
    }
    if (n > 1) {
      fwrite(p, 1, (size_t)n, out);
      p += n;
      continue;
    }
    switch (c) {
    case '"': fputs("\\\"", out); break;
    case '\\': fputs("\\\\", out); break;
    case '\n': fputs("\\n", out); break;
    case '\r': fputs("\\r", out); break;
    case '\t': fputs("\\t", out); break;
    case '\b': fputs("\\b", out); break;
    case '\f': fputs("\\f", out); break;
    default:
      if (c < 0x20 || c == 0x7F) fprintf(out, "\\u%04x", c);
      else fputc(c, out);
    }
    ++p;
  }
  fputc('"', out);
}

void cli_json_init(cli_json *j, FILE *out)
{
  j->out = out;
  j->depth = 0;
  j->count[0] = 0;
}

/* the comma and the key before a value */
static void lead(cli_json *j, const char *key)
{
  if (j->count[j->depth]++ > 0) fputc(',', j->out);
  if (key) {
    cli_json_quote(j->out, key);
    fputc(':', j->out);
  }
}

static void open_value(cli_json *j, const char *key, char c)
{
  lead(j, key);
  fputc(c, j->out);
  if (j->depth + 1 < CLI_JSON_DEPTH) {
    ++j->depth;
    j->count[j->depth] = 0;
    j->close[j->depth] = c == '{' ? '}' : ']';
  }
}

void cli_json_object(cli_json *j, const char *key) { open_value(j, key, '{'); }
void cli_json_array(cli_json *j, const char *key) { open_value(j, key, '['); }

void cli_json_end(cli_json *j)
{
  if (j->depth == 0) return;
  fputc(j->close[j->depth--], j->out);
  if (j->depth == 0) fputc('\n', j->out);
}

void cli_json_string(cli_json *j, const char *key, const char *v)
{
  lead(j, key);
  if (v) cli_json_quote(j->out, v);
  else fputs("null", j->out);
}

void cli_json_number(cli_json *j, const char *key, double v)
{
  lead(j, key);
  if (!isfinite(v)) {
    fputs("null", j->out);
    return;
  }
  /* the shortest of 15 and 17 digits that reads back to the same double */
  char buf[32];
  snprintf(buf, sizeof buf, "%.15g", v);
  if (strtod(buf, NULL) != v) snprintf(buf, sizeof buf, "%.17g", v);
  fputs(buf, j->out);
}

void cli_json_int(cli_json *j, const char *key, long long v)
{
  lead(j, key);
  fprintf(j->out, "%lld", v);
}

void cli_json_bool(cli_json *j, const char *key, int v)
{
  lead(j, key);
  fputs(v ? "true" : "false", j->out);
}

void cli_json_null(cli_json *j, const char *key)
{
  lead(j, key);
  fputs("null", j->out);
}
