/* A small JSON writer for the CLI's --json summaries (docs/cli.md, "JSON"). It writes one
 * value at a time, placing the commas itself. Strings are escaped (quote, backslash,
 * control characters as \uXXXX; bytes that are not UTF-8 become U+FFFD), numbers are
 * written to round-trip (%.17g) and a number that is not finite is written as null:
 * JSON has no NaN. */
#ifndef RS_CLI_JSON_H
#define RS_CLI_JSON_H

#include <stdio.h>

enum { CLI_JSON_DEPTH = 16 }; /* nesting the summaries need, with room to spare */

typedef struct cli_json {
  FILE *out;
  int depth;
  int count[CLI_JSON_DEPTH]; /* values written so far at each level */
  char close[CLI_JSON_DEPTH]; /* '}' or ']' for each level open */
} cli_json;

void cli_json_init(cli_json *j, FILE *out);
/* `key` names the value inside an object; NULL inside an array or at the top. */
void cli_json_object(cli_json *j, const char *key);
void cli_json_array(cli_json *j, const char *key);
void cli_json_end(cli_json *j); /* closes the innermost object or array */
void cli_json_string(cli_json *j, const char *key, const char *v); /* NULL: null */
void cli_json_number(cli_json *j, const char *key, double v);      /* not finite: null */
void cli_json_int(cli_json *j, const char *key, long long v);
void cli_json_bool(cli_json *j, const char *key, int v);
void cli_json_null(cli_json *j, const char *key);

/* Writes s as a JSON string (with its quotes). */
void cli_json_quote(FILE *out, const char *s);

#endif
