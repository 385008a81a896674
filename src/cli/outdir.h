/* Output directories the commands make as needed (plot -o DIR, run --csv DIR, study -o DIR)
 * with the rules of mkdir -p: every missing component is made (mode 0777 less the umask);
 * one that exists must be a directory. */
#ifndef RS_CLI_OUTDIR_H
#define RS_CLI_OUTDIR_H

typedef struct cli_outdir {
  char *path; /* DIR as given */
  char *top;  /* the uppermost directory cli_outdir_make made, or NULL */
} cli_outdir;

/* Before any work: can DIR be had? Every component of it that exists is a directory
 * (else exit 2, naming it: "<label> 'a/b': 'a' is not a directory"), and the deepest one
 * that exists is writable (else exit 1). Returns 0 or the exit status, message printed. */
int cli_outdir_check(const char *label, const char *dir);

/* Makes DIR and its missing parents (mkdir -p), recording what it made in *made (freed by
 * cli_outdir_free). Returns 0 or the exit status (2 not a directory, 1 any other failure),
 * message printed. */
int cli_outdir_make(const char *label, const char *dir, cli_outdir *made);

/* Removes the directories cli_outdir_make made, deepest first, as long as they are empty:
 * a command that then failed leaves nothing behind. Then frees. */
void cli_outdir_undo(cli_outdir *made);
void cli_outdir_free(cli_outdir *made);

#endif
