/* Where shipped material models are looked up after the scene's own folders. */
#ifndef RS_SCENE_MODEL_DIRS_H
#define RS_SCENE_MODEL_DIRS_H

#include "reelsim/scene.h" /* RS_PATH_MAX */

enum { YS_MODEL_DIRS_MAX = 4 };

/* Fills dirs with the model folders to try, in order, and returns how many:
 *   1. $REELSIM_MODELS when set;
 *   2. a build-tree program (the code runs from under the build folder): the source
 *      tree's models/;
 *   3. otherwise the installed <datadir>/reelsim/models, found relative to the library or
 *      program that holds this code (so a moved install still finds its models), then
 *      at the install prefix it was configured for. */
int rsi_ys_model_dirs(char dirs[][RS_PATH_MAX], int max);

#endif
