# test/regress/stage.sh — sourced by the tests that build against the
# installed whirl (example_ab.sh, user_model.sh, run_api.sh), after they
# set top_builddir and tmp.  Sets stage (the staged install: the one make
# check made before the tests run, as WHIRL_STAGE — an install during the
# tests would relink the libraries under the tests running — or, run
# alone, one of the script's own), prefix, libdir, pcdir, incdir and whirl
# (the installed command), and defines stage_make DIR TARGET...: make
# against the staged whirl.pc through pkg-config.
# SPDX-License-Identifier: BSD-3-Clause
stage=${WHIRL_STAGE:-}
if [ -z "$stage" ] || [ ! -d "$stage" ]; then
  stage="$tmp/stage"
  ${MAKE:-make} -s -C "$top_builddir" install DESTDIR="$stage" > "$tmp/install.log" 2>&1 ||
    rm -rf "$stage"
fi
prefix=$(sed -n 's/^prefix=//p' "$top_builddir/whirl.pc")
libdir=$(sed -n 's/^libdir=//p' "$top_builddir/whirl.pc" |
         sed "s|\${exec_prefix}|$prefix|; s|\${prefix}|$prefix|")
pcdir="$stage$libdir/pkgconfig"
incdir="$stage$prefix/include"
whirl="$stage$prefix/bin/whirl"
# /usr/local/include and /usr/local/lib count as system paths to pkgconf
# and would be dropped before the sysroot is applied: keep them.
stage_make() {
  PKG_CONFIG_ALLOW_SYSTEM_CFLAGS=1 PKG_CONFIG_ALLOW_SYSTEM_LIBS=1 \
  PKG_CONFIG_SYSROOT_DIR="$stage" PKG_CONFIG_LIBDIR="$pcdir" \
    ${MAKE:-make} -s -C "$@"
}
