# m4/whirl_lazy.m4 — WHIRL_LAZY(NAME, LIBS): the libraries LIBS (-lfoo ...)
# of an optional backend opened at its first use (whirl/dynlib.h) rather
# than at every start.  Their sonames are read from a program linked with
# them (objdump -p: its NEEDED entries); when every one is found,
# WHIRL_SONAMES_NAME is defined to their ':'-separated list and NAME_LINK
# is empty, and WHIRL_DYNLIB_NAME(T, L) declares a table T of the functions
# L bound from them; else (or with --disable-lazy-libraries) NAME_LINK is
# LIBS, the backend is linked as usual, and whirl/dynlib.h's
# WHIRL_DYNLIB_NAME makes T the functions' own addresses.
# SPDX-License-Identifier: BSD-3-Clause
AC_DEFUN([WHIRL_LAZY_INIT], [
  AC_ARG_ENABLE([lazy-libraries],
    [AS_HELP_STRING([--disable-lazy-libraries],
      [link UMFPACK, SUNDIALS, ARPACK, CHOLMOD and FFTW into every program instead of opening them at their first use])],
    [], [enable_lazy_libraries=yes])
  AC_CHECK_TOOL([OBJDUMP], [objdump], [false])
])

AC_DEFUN([WHIRL_LAZY], [
  AC_REQUIRE([WHIRL_LAZY_INIT])
  $1_LINK="$2"
  whirl_sonames=
  # a library found through -L is linked: dlopen would not search there
  AS_CASE([" $2 "], [*" -L"*], [whirl_lazy_ok=no], [whirl_lazy_ok=$enable_lazy_libraries])
  AS_IF([test "x$whirl_lazy_ok" != xno && test "x$OBJDUMP" != xfalse], [
    AC_MSG_CHECKING([for the sonames of $1 ($2)])
    whirl_save_LIBS=$LIBS
    LIBS="-Wl,--no-as-needed $2 $LAPACK_LIBS $BLAS_LIBS $LIBM $LIBS"
    AC_LINK_IFELSE([AC_LANG_PROGRAM([], [])], [
      whirl_needed=`$OBJDUMP -p conftest$ac_exeext 2>/dev/null | sed -n 's/^ *NEEDED *//p'`
      for whirl_flag in $2; do
        AS_CASE([$whirl_flag],
          [-l*], [whirl_lib=lib`echo "$whirl_flag" | sed 's/^-l//'`.so
                  whirl_so=
                  for whirl_n in $whirl_needed; do
                    AS_CASE([$whirl_n], ["$whirl_lib" | "$whirl_lib".*], [whirl_so=$whirl_n])
                  done
                  AS_IF([test -z "$whirl_so"], [whirl_sonames=none; break])
                  whirl_sonames=${whirl_sonames:+$whirl_sonames:}$whirl_so])
      done])
    LIBS=$whirl_save_LIBS
    AS_IF([test -z "$whirl_sonames"], [whirl_sonames=none])
    AC_MSG_RESULT([$whirl_sonames])
    AS_IF([test "x$whirl_sonames" != xnone], [
      AC_DEFINE_UNQUOTED([WHIRL_SONAMES_$1], ["$whirl_sonames"],
        [the libraries of $1, opened at their first use (whirl/dynlib.h)])
      AC_DEFINE_UNQUOTED([WHIRL_DYNLIB_$1(T, L)], [WHIRL_DYNLIB(T, L, "$whirl_sonames")],
        [the table T of $1's functions L, bound at their first use (whirl/dynlib.h)])
      $1_LINK=
    ])
  ])
  AC_SUBST([$1_LINK])
])
