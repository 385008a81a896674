/* rs_scene_load_text: a scene held in memory loads exactly as the same file does, reads
 * only the `len` bytes it is given, and refuses empty or missing text as input errors. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reelsim/scene.h"
#include "scene/scene_type.h" /* the fields: these tests look inside */

#ifndef RS_ROOT_DIR
#error "RS_ROOT_DIR must name the project root"
#endif

static char *slurp(const char *path, size_t *len)
{
  *len = 0;
  FILE *f = fopen(path, "rb");
  CHECK(f != NULL);
  if (!f) return NULL;
  char *buf = malloc(1 << 16);
  *len = fread(buf, 1, (1 << 16) - 1, f);
  buf[*len] = '\0';
  fclose(f);
  return buf;
}

/* every shipped case: same resolved text (the name stands for the path) */
static void matches_file(void)
{
  const char *dir = RS_ROOT_DIR "/cases";
  DIR *d = opendir(dir);
  CHECK(d != NULL);
  if (!d) return;
  int n = 0;
  for (struct dirent *e; (e = readdir(d));) {
    if (!strstr(e->d_name, ".yaml")) continue;
    char path[1024];
    size_t len;
    snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
    char *text = slurp(path, &len);
    rs_scene *a = NULL, *b = NULL;
    CHECK(rs_scene_load(path, 0, NULL, &a) == RS_OK);
    CHECK(rs_scene_load_text(path, text, len, 0, NULL, &b) == RS_OK);
    if (a && b) {
      CHECK(strcmp(a->resolved_text, b->resolved_text) == 0);
      CHECK(a->problem.n_layers == b->problem.n_layers);
    }
    printf("  %s: %s\n", e->d_name, a && b ? "same" : "failed");
    rs_scene_destroy(&a);
    rs_scene_destroy(&b);
    free(text);
    ++n;
  }
  closedir(d);
  CHECK(n >= 4);
}

/* only len bytes are read: garbage after them (no NUL) does not matter */
static void reads_len_bytes(void)
{
  static const char scene[] = "material: {caliper: 1.0e-4, E_theta: 4.0e9, "
                              "radial: {law: linear, E_r: 2.0e7}}\n"
                              "core: {radius: 0.05}\n"
                              "winding: {final_radius: 0.07, tension: 200}\n";
  size_t len = strlen(scene);
  char *buf = malloc(len + 8);
  memcpy(buf, scene, len);
  memcpy(buf + len, "]]]]:::!", 8); /* not terminated, and not YAML */
  rs_scene *s = NULL;
  CHECK(rs_scene_load_text("mem.yaml", buf, len, 0, NULL, &s) == RS_OK);
  if (s) {
    CHECK(s->problem.n_layers == 200);
    CHECK(strcmp(s->title, "mem") == 0);         /* default title from the name */
    CHECK(strcmp(s->output.file, "mem.h5") == 0); /* default output from the name */
  }
  rs_scene_destroy(&s);
  free(buf);
}

static void empty_and_null(void)
{
  rs_scene *s = (rs_scene *)1;
  CHECK(rs_scene_load_text("empty.yaml", "", 0, 0, NULL, &s) == RS_ERR_INPUT);
  CHECK(s == NULL);
  CHECK(strstr(rs_error_message(), "empty.yaml: the file is empty") != NULL);
  CHECK(rs_scene_load_text("null.yaml", NULL, 0, 0, NULL, &s) == RS_ERR_INPUT);
  CHECK(rs_scene_load_text("null.yaml", NULL, 5, 0, NULL, &s) == RS_ERR_INTERNAL);
  CHECK(rs_scene_load_text("", "a: 1", 4, 0, NULL, &s) == RS_ERR_INPUT);
  printf("  %s\n", rs_error_message());
}

/* A name only the API can give: a 600-byte stem still loads (the default title is cut to
 * the 511 bytes a title may have, at a character boundary); a 4093-byte one cannot name
 * the output file after itself, so it is an input error, not an internal one. */
static void long_names(void)
{
  static const char scene[] = "material: {caliper: 1.0e-4, E_theta: 4.0e9, "
                              "radial: {law: linear, E_r: 2.0e7}}\n"
                              "core: {radius: 0.05}\n"
                              "winding: {final_radius: 0.07, tension: 200}\n";
  static char name[4200];
  rs_scene *s = NULL;
  memset(name, 'a', 510);
  strcpy(name + 510, "\xc3\xa9\xc3\xa9.yaml"); /* two 2-byte characters across byte 511 */
  CHECK(rs_scene_load_text(name, scene, strlen(scene), 0, NULL, &s) == RS_OK);
  if (s) {
    CHECK(strlen(s->title) == 510); /* not 511: that would split the first character */
    CHECK(s->title[509] == 'a');
  }
  rs_scene_destroy(&s);
  memset(name, 'b', 4093);
  strcpy(name + 4093, ".y"); /* 4095 bytes: the longest path there is */
  CHECK(rs_scene_load_text(name, scene, strlen(scene), 0, NULL, &s) == RS_ERR_INPUT);
  CHECK(strstr(rs_error_message(), "give output.file") != NULL);
  printf("  %.60s\n", rs_error_message() + 70);
}

static const check_case cases[] = {
    {"long_names", long_names},
    {"matches_file", matches_file},
    {"reads_len_bytes", reads_len_bytes},
    {"empty_and_null", empty_and_null},
};

int main(int argc, char **argv) { return CHECK_MAIN(argc, argv, cases); }
