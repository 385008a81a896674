/* cli_shown: text from a scene made safe to print (see fail.h). */
#include <stdio.h>
#include <string.h>

#include "cli/fail.h"

const char *cli_shown(const char *s, char *buf, size_t size)
{
  size_t n = 0;
  if (size == 0) return "";
  for (const unsigned char *p = (const unsigned char *)(s ? s : ""); *p && n + 5 < size; ++p) {
    if (*p == '\n') n += (size_t)snprintf(buf + n, size - n, "\\n");
    else if (*p == '\t') n += (size_t)snprintf(buf + n, size - n, "\\t");
    else if (*p < 0x20 || *p == 0x7f) n += (size_t)snprintf(buf + n, size - n, "\\x%02x", *p);
    else buf[n++] = (char)*p;
  }
  buf[n] = '\0';
  return buf;
}
