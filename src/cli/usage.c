/* Help texts: see usage.h. Every option a command takes is listed, from the same table
 * the parser reads. */
#include "cli/usage.h"

#include <string.h>

enum { HELP_COLUMN = 17 };

/* Prints `text` with every line after the first indented to the help column. */
static void indented(FILE *out, const char *text)
{
  for (const char *p = text; *p; ++p) {
    fputc(*p, out);
    if (*p == '\n') fprintf(out, "%*s", HELP_COLUMN, "");
  }
  fputc('\n', out);
}

static void print_option(FILE *out, const cli_option *o)
{
  char flag[96];
  if (o->short_name)
    snprintf(flag, sizeof flag, "  -%c, --%s%s%s", o->short_name, o->name, o->arg ? " " : "",
             o->arg ? o->arg : "");
  else
    snprintf(flag, sizeof flag, "  --%s%s%s", o->name, o->arg ? " " : "", o->arg ? o->arg : "");
  size_t len = strlen(flag);
  if (len < HELP_COLUMN - 1)
    fprintf(out, "%s%*s", flag, (int)(HELP_COLUMN - len), "");
  else
    fprintf(out, "%s\n%*s", flag, HELP_COLUMN, "");
  indented(out, o->help);
}

static void print_general(FILE *out)
{
  fputs("usage: reelsim <command> [options]\n"
        "\n"
        "Simulates winding a reel (paper, film) and the stresses wound into it.\n"
        "\n"
        "commands:\n",
        out);
  for (int i = 0; i < cli_n_commands; ++i) {
    const cli_command *c = &cli_commands[i];
    char head[64];
    snprintf(head, sizeof head, "  %s %s", c->name,
             c->many ? "SCENE1 SCENE2 ..." : strcmp(c->operand, "file") == 0 ? "FILE.h5" : "SCENE");
    size_t len = strlen(head);
    if (len < HELP_COLUMN - 1)
      fprintf(out, "%s%*s", head, (int)(HELP_COLUMN - len), "");
    else
      fprintf(out, "%s\n%*s", head, HELP_COLUMN, "");
    indented(out, c->summary);
  }
  fputs("  fit stack TEST.csv | fit roll SCENE\n"
        "                 calibrate: a stack law fitted to a stack test, or scene keys\n"
        "                 fitted to a roll's measured diameters, pressures or WIT\n"
        "                 (reelsim fit --help)\n"
        "  help [CMD]     this text, or one command's (also: reelsim CMD --help)\n"
        "\n"
        "options:\n"
        "  --version      print the version\n"
        "  -h, --help     this help (after a command, that command's:\n"
        "                 reelsim run --help)\n"
        "\n"
        "exit status: 0 ok, 2 bad input or usage, 3 the solver failed,\n"
        "             130 interrupted (Ctrl-C), 143 terminated (SIGTERM), 1 anything else\n"
        "Scene files: docs/scenes.md. Command line: docs/cli.md.\n",
        out);
}

void cli_usage(FILE *out, const cli_command *cmd)
{
  if (!cmd) {
    print_general(out);
    return;
  }
  fprintf(out, "usage: %s\n\n%s\noptions:\n", cmd->synopsis, cmd->about);
  for (int i = 0; i < cli_n_options; ++i)
    if (cli_options[i].cmds & cmd->bit) print_option(out, &cli_options[i]);
  fprintf(out, "\n%s", cmd->footer);
}

void cli_command_names(char *buf, size_t size)
{
  size_t used = 0;
  buf[0] = '\0';
  for (int i = 0; i < cli_n_commands && used < size; ++i)
    used += (size_t)snprintf(buf + used, size - used, "%s, ", cli_commands[i].name);
  if (used < size) snprintf(buf + used, size - used, "help");
}
