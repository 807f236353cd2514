check backup-prog.pgf
