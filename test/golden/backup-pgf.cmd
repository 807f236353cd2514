run backup-prog.pgf
