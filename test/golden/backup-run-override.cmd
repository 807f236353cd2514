run --task T_STATE=backup-idle.mod --entry T_STATE=main backup-cell
