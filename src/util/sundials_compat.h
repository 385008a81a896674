/* What reelsim needs from SUNDIALS that changed between 6.x and 7.x, in one place.
 * Private to the library (src/); reelsim builds against SUNDIALS 6.4 to 7.x (CMake checks
 * the range, this header the headers it is compiled against; docs/development.md).
 *
 * SUNDIALS 7.0 changed, for what reelsim uses:
 *  - SUNContext_Create takes a SUNComm (SUN_COMM_NULL without MPI), not a void * (NULL);
 *  - errors go to a stack of handlers on the context (SUNContext_PushErrHandler: line,
 *    function, file, message, SUNErrCode), not to a per-solver CVodeSetErrHandlerFn; the
 *    default handler prints to stderr, and CVODE's warnings go to the context's SUNLogger,
 *    which prints them to stdout by default;
 *  - the 6.x return codes SUNLS_SUCCESS, SUN_NLS_SUCCESS, SUN_NLS_MEM_NULL,
 *    SUN_NLS_ILL_INPUT and SUNLS_PACKAGE_FAIL_UNREC became SUN_SUCCESS and the SUN_ERR_*
 *    codes (SUNErrCode); the positive (recoverable) ones SUN_NLS_CONTINUE,
 *    SUN_NLS_CONV_RECVR, SUNLS_RES_REDUCED and SUNLS_CONV_FAIL stay;
 *  - realtype and booleantype are gone (sunrealtype and sunbooleantype, which 6.x has too). */
#ifndef REELSIM_UTIL_SUNDIALS_COMPAT_H
#define REELSIM_UTIL_SUNDIALS_COMPAT_H

#include <sundials/sundials_config.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_nonlinearsolver.h>

#if !defined(SUNDIALS_VERSION_MAJOR) || SUNDIALS_VERSION_MAJOR < 6 || \
    (SUNDIALS_VERSION_MAJOR == 6 && SUNDIALS_VERSION_MINOR < 4) || SUNDIALS_VERSION_MAJOR > 7
#error "reelsim builds against SUNDIALS 6.4 to 7.x (sundials_config.h says otherwise)"
#endif

#if SUNDIALS_VERSION_MAJOR >= 7
/* the 6.x names of the codes reelsim's solvers return, as SUNDIALS 7 spells them */
#define SUNLS_SUCCESS SUN_SUCCESS
#define SUNLS_PACKAGE_FAIL_UNREC SUN_ERR_EXT_FAIL
#define SUN_NLS_SUCCESS SUN_SUCCESS
#define SUN_NLS_MEM_NULL SUN_ERR_ARG_CORRUPT
#define SUN_NLS_ILL_INPUT SUN_ERR_ARG_OUTOFRANGE
#endif

/* The length of the message buffers rs_sundials_cvode_messages writes */
enum { RS_SUNDIALS_MSG_LEN = 512 };

/* A SUNDIALS context that prints nothing (no communicator: reelsim's solvers are serial).
 * SUNDIALS 6.4 as Debian builds it prints nothing; SUNDIALS 7 would print errors to stderr
 * and warnings to stdout (a library must not), so its default error handler is removed
 * and, unless SUNDIALS was built with extra debugging output (logging level 5, whose
 * macros read the logger unchecked), its logger detached: CVODE's warnings are dropped,
 * its errors reach the handler rs_sundials_cvode_messages installs or none. 0, or -1. */
int rs_sundials_context_create(SUNContext *ctx);

/* CVODE's error messages into msg, as "<module> <function> (code <n>): <message>": each
 * replaces the last (6.x: CVodeSetErrHandlerFn on cvode_mem, which also reports warnings;
 * 7.x: a handler on ctx, the context cvode_mem was created with, for errors). msg must
 * outlive the solver. 0, or -1. */
int rs_sundials_cvode_messages(void *cvode_mem, SUNContext ctx, char (*msg)[RS_SUNDIALS_MSG_LEN]);

#endif
