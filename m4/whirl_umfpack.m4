# whirl_umfpack.m4 — find SuiteSparse's UMFPACK (sparse LU).  Debian's
# libsuitesparse-dev puts the headers in /usr/include/suitesparse and ships no
# .pc file for it, so look for the header in both places and the library.
AC_DEFUN([WHIRL_CHECK_UMFPACK], [
  AC_ARG_VAR([UMFPACK_CFLAGS], [C flags for UMFPACK])
  AC_ARG_VAR([UMFPACK_LIBS], [linker flags for UMFPACK])
  whirl_save_CPPFLAGS=$CPPFLAGS
  whirl_save_LIBS=$LIBS
  AS_IF([test "x$UMFPACK_CFLAGS" = x], [
    AS_IF([test -f /usr/include/suitesparse/umfpack.h],
          [UMFPACK_CFLAGS="-I/usr/include/suitesparse"])
  ])
  CPPFLAGS="$CPPFLAGS $UMFPACK_CFLAGS"
  AC_CHECK_HEADER([umfpack.h], [],
    [AC_MSG_ERROR([UMFPACK header umfpack.h not found. On Debian: apt-get install libsuitesparse-dev])])
  AS_IF([test "x$UMFPACK_LIBS" = x], [
    LIBS="$LAPACK_LIBS $BLAS_LIBS $LIBM $whirl_save_LIBS"
    AC_SEARCH_LIBS([umfpack_di_numeric], [umfpack],
      [UMFPACK_LIBS="$ac_cv_search_umfpack_di_numeric"],
      [AC_MSG_ERROR([UMFPACK library not found. On Debian: apt-get install libsuitesparse-dev])])
    AS_IF([test "x$UMFPACK_LIBS" = "xnone required"], [UMFPACK_LIBS=""])
    # KLU, the default sparse LU (lib/linalg/sparse.c), beside UMFPACK
    LIBS="$UMFPACK_LIBS $LAPACK_LIBS $BLAS_LIBS $LIBM $whirl_save_LIBS"
    AC_SEARCH_LIBS([klu_factor], [klu],
      [AS_IF([test "x$ac_cv_search_klu_factor" != "xnone required"],
             [UMFPACK_LIBS="$UMFPACK_LIBS $ac_cv_search_klu_factor"])],
      [AC_MSG_ERROR([KLU library not found. On Debian: apt-get install libsuitesparse-dev])])
  ])
  AC_CHECK_HEADER([klu.h], [],
    [AC_MSG_ERROR([KLU header klu.h not found. On Debian: apt-get install libsuitesparse-dev])])
  CPPFLAGS=$whirl_save_CPPFLAGS
  LIBS=$whirl_save_LIBS
])
