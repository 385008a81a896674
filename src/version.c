/* The library's version (reelsim/version.h): compiled in here, so a program linked to a
 * shared libreelsim reports the library it runs with, not the headers it was built with. */
#include "reelsim/version.h"

const char *rs_version(void) { return RS_VERSION_STRING; }
