/* What a public header declares is reelsim's API: RS_BEGIN_DECLS / RS_END_DECLS open and
 * close every public header's declarations.
 *
 * The library is compiled with hidden visibility (-fvisibility=hidden), so only what is
 * declared between these two marks is exported from the shared library; the helpers that
 * one source file shares with another stay internal. For C++ they also give the
 * declarations C linkage. */
#ifndef REELSIM_EXPORT_H
#define REELSIM_EXPORT_H

#if defined(__GNUC__) || defined(__clang__)
#define RS_VISIBILITY_PUSH_ _Pragma("GCC visibility push(default)")
#define RS_VISIBILITY_POP_ _Pragma("GCC visibility pop")
#else
#define RS_VISIBILITY_PUSH_
#define RS_VISIBILITY_POP_
#endif

#ifdef __cplusplus
#define RS_BEGIN_DECLS extern "C" { RS_VISIBILITY_PUSH_
#define RS_END_DECLS RS_VISIBILITY_POP_ }
#else
#define RS_BEGIN_DECLS RS_VISIBILITY_PUSH_
#define RS_END_DECLS RS_VISIBILITY_POP_
#endif

#endif
