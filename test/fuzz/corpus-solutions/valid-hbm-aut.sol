# whirl solutions: model ab, npar 3
LAB 2 TY UZ BR 1 PT 0 KIND hbm ICP 1 ICP2 0 NX 11 STAB 1 NHB 2
PAR 0.16 14 3
X 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5
END
