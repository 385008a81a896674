/* The older internal name of the version header, kept for the files that include it. */
#include "reelsim/version.h"
