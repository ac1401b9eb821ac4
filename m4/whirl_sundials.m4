# whirl_sundials.m4 — find SUNDIALS CVODE (version 6: SUNContext, the
# CVodeSetErrHandlerFn error handler) with its serial vectors, dense and KLU
# sparse linear solvers (BDF in lib/ode/bdf.c).  Debian's libsundials-dev
# ships no .pc file and its sunlinsol_klu.h includes SuiteSparse's klu.h, so
# look for the headers (with /usr/include/suitesparse) and the libraries.
AC_DEFUN([WHIRL_CHECK_SUNDIALS], [
  AC_ARG_VAR([SUNDIALS_CFLAGS], [C flags for SUNDIALS CVODE])
  AC_ARG_VAR([SUNDIALS_LIBS], [linker flags for SUNDIALS CVODE with KLU])
  whirl_save_CPPFLAGS=$CPPFLAGS
  whirl_save_LIBS=$LIBS
  AS_IF([test "x$SUNDIALS_CFLAGS" = x && test -f /usr/include/suitesparse/klu.h],
        [SUNDIALS_CFLAGS="-I/usr/include/suitesparse"])
  CPPFLAGS="$CPPFLAGS $SUNDIALS_CFLAGS"
  whirl_sundials_hint="On Debian: apt-get install libsundials-dev libsuitesparse-dev"
  AC_CHECK_HEADERS([cvode/cvode.h sunlinsol/sunlinsol_klu.h], [],
    [AC_MSG_ERROR([SUNDIALS CVODE with KLU not found ($ac_header). $whirl_sundials_hint])])
  AC_MSG_CHECKING([for SUNDIALS version 6])
  AC_COMPILE_IFELSE([AC_LANG_PROGRAM([[#include <sundials/sundials_config.h>]],
    [[#if SUNDIALS_VERSION_MAJOR != 6
#error not 6
#endif]])], [AC_MSG_RESULT([yes])],
    [AC_MSG_RESULT([no])
     AC_MSG_ERROR([whirl needs SUNDIALS 6.x (the CVODE 6 API). $whirl_sundials_hint])])
  AS_IF([test "x$SUNDIALS_LIBS" = x], [
    SUNDIALS_LIBS="-lsundials_cvode -lsundials_nvecserial -lsundials_sunmatrixdense -lsundials_sunlinsoldense -lsundials_sunmatrixsparse -lsundials_sunlinsolklu -lklu"
  ])
  LIBS="$SUNDIALS_LIBS $LIBM $whirl_save_LIBS"
  AC_MSG_CHECKING([for CVODE with the KLU linear solver])
  AC_LINK_IFELSE([AC_LANG_PROGRAM([[#include <cvode/cvode.h>
#include <sunlinsol/sunlinsol_klu.h>]],
    [[SUNContext c; void *m; SUNContext_Create(NULL, &c); m = CVodeCreate(CV_BDF, c);
      CVodeSetErrHandlerFn(m, NULL, NULL); (void)SUNLinSol_KLU(NULL, NULL, c);]])],
    [AC_MSG_RESULT([yes])],
    [AC_MSG_RESULT([no])
     AC_MSG_ERROR([cannot link CVODE with KLU ($SUNDIALS_LIBS). $whirl_sundials_hint])])
  CPPFLAGS=$whirl_save_CPPFLAGS
  LIBS=$whirl_save_LIBS
])
