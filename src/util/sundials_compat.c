/* SUNDIALS 6.4 and 7.x behind one interface (sundials_compat.h). */
#include "util/sundials_compat.h"

#include <stdio.h>
#include <string.h>

#include <cvode/cvode.h>
#if SUNDIALS_VERSION_MAJOR >= 7
#include <sundials/sundials_logger.h>
#endif

#if SUNDIALS_VERSION_MAJOR >= 7

int rs_sundials_context_create(SUNContext *ctx)
{
  *ctx = NULL;
  if (SUNContext_Create(SUN_COMM_NULL, ctx) != SUN_SUCCESS || !*ctx) return -1;
  int bad = SUNContext_ClearErrHandlers(*ctx) != SUN_SUCCESS;
#if SUNDIALS_LOGGING_LEVEL < 5
  bad = bad || SUNContext_SetLogger(*ctx, NULL) != SUN_SUCCESS;
#endif
  if (bad) {
    SUNContext_Free(ctx);
    return -1;
  }
  return 0;
}

/* 7.x: the handler gets where (file, line, function) and SUNDIALS' code: CVODE's CV_*
 * code for CVODE's errors, a SUN_ERR_* code for the shared modules' */
static void cvode_message(int line, const char *function, const char *file, const char *text,
                          SUNErrCode code, void *user, SUNContext ctx)
{
  (void)line;
  (void)ctx;
  const char *base = file ? strrchr(file, '/') : NULL;
  base = base ? base + 1 : file ? file : "";
  const char *module = strncmp(base, "cvode", 5) == 0 ? "CVODE" : "SUNDIALS";
  snprintf(*(char (*)[RS_SUNDIALS_MSG_LEN])user, RS_SUNDIALS_MSG_LEN, "%s %s (code %d): %s",
           module, function ? function : "?", (int)code, text ? text : "");
}

int rs_sundials_cvode_messages(void *cvode_mem, SUNContext ctx, char (*msg)[RS_SUNDIALS_MSG_LEN])
{
  (void)cvode_mem;
  return SUNContext_PushErrHandler(ctx, cvode_message, msg) == SUN_SUCCESS ? 0 : -1;
}

#else /* SUNDIALS 6.4 */

int rs_sundials_context_create(SUNContext *ctx)
{
  *ctx = NULL;
  return SUNContext_Create(NULL, ctx) == 0 && *ctx ? 0 : -1;
}

static void cvode_message(int code, const char *module, const char *function, char *text,
                          void *user)
{
  snprintf(*(char (*)[RS_SUNDIALS_MSG_LEN])user, RS_SUNDIALS_MSG_LEN, "%s %s (code %d): %s",
           module, function, code, text);
}

int rs_sundials_cvode_messages(void *cvode_mem, SUNContext ctx, char (*msg)[RS_SUNDIALS_MSG_LEN])
{
  (void)ctx;
  return CVodeSetErrHandlerFn(cvode_mem, cvode_message, msg) == CV_SUCCESS ? 0 : -1;
}

#endif
