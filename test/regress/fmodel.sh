# test/regress/fmodel.sh — sourced by the tests of `whirl auto`:
#   fmodel FILE 'FUNC line' ... -- 'STPNT line' ...
# writes an AUTO-07p equations file FILE with FUNC and STPNT holding those
# statements, with the declarations every such file repeats (the tests'
# one-line models: u' = p u - u^2, p = u^2, ...).
# SPDX-License-Identifier: BSD-3-Clause
fmodel() {
  fmodel_file=$1
  shift
  {
    printf '      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)\n'
    printf '      IMPLICIT NONE\n      INTEGER NDIM, IJAC, ICP(*)\n'
    printf '      DOUBLE PRECISION U(NDIM), PAR(*), F(NDIM), DFDU(NDIM,NDIM), DFDP(*)\n'
    while [ $# -gt 0 ] && [ "$1" != -- ]; do
      printf '      %s\n' "$1"
      shift
    done
    [ $# -gt 0 ] && shift
    printf '      END SUBROUTINE FUNC\n      SUBROUTINE STPNT(NDIM,U,PAR,T)\n'
    printf '      IMPLICIT NONE\n      INTEGER NDIM\n      DOUBLE PRECISION U(NDIM), PAR(*), T\n'
    for fmodel_line in "$@"; do printf '      %s\n' "$fmodel_line"; done
    printf '      END SUBROUTINE STPNT\n'
  } > "$fmodel_file"
}
