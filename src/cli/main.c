/* reelsim command-line entry point (placeholder until the CLI module lands). */
#include <stdio.h>

#include "reelsim_version.h"

int main(int argc, char **argv)
{
  (void)argc;
  (void)argv;
  printf("reelsim %s\n", RS_VERSION_STRING);
  return 0;
}
