# whirl_lapack.m4 — find BLAS and LAPACK.  pkg-config's lapack/blas first
# (Debian ships lapack.pc and blas.pc), then a plain library search.  A missing
# one stops configure with the Debian package to install.
AC_DEFUN([WHIRL_CHECK_LAPACK], [
  PKG_CHECK_MODULES([LAPACK], [lapack], [whirl_have_lapack=yes],
                    [whirl_have_lapack=no])
  PKG_CHECK_MODULES([BLAS], [blas], [whirl_have_blas=yes],
                    [whirl_have_blas=no])
  whirl_save_LIBS=$LIBS
  AS_IF([test "x$whirl_have_blas" = xno], [
    AC_SEARCH_LIBS([dgemm_], [blas openblas], [BLAS_LIBS="$ac_cv_search_dgemm_"],
      [AC_MSG_ERROR([BLAS not found. On Debian: apt-get install libblas-dev])], [$LIBM])
  ])
  AS_IF([test "x$BLAS_LIBS" = "xnone required"], [BLAS_LIBS=""])
  LIBS="$BLAS_LIBS $LIBM $whirl_save_LIBS"
  AS_IF([test "x$whirl_have_lapack" = xno], [
    AC_SEARCH_LIBS([dgetrf_], [lapack openblas], [LAPACK_LIBS="$ac_cv_search_dgetrf_"],
      [AC_MSG_ERROR([LAPACK not found. On Debian: apt-get install liblapack-dev])])
  ])
  AS_IF([test "x$LAPACK_LIBS" = "xnone required"], [LAPACK_LIBS=""])
  # The prototypes whirl declares are Fortran's: check that they link.
  LIBS="$LAPACK_LIBS $BLAS_LIBS $LIBM $whirl_save_LIBS"
  AC_MSG_CHECKING([that dgeev_ and dgesvd_ link])
  AC_LINK_IFELSE([AC_LANG_PROGRAM([[void dgeev_(void); void dgesvd_(void);]],
                                  [[dgeev_(); dgesvd_();]])],
    [AC_MSG_RESULT([yes])],
    [AC_MSG_RESULT([no])
     AC_MSG_ERROR([LAPACK found but dgeev_/dgesvd_ do not link. On Debian: apt-get install liblapack-dev libblas-dev])])
  LIBS=$whirl_save_LIBS
  AC_SUBST([LAPACK_LIBS])
  AC_SUBST([BLAS_LIBS])
])
