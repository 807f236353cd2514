MODULE linked_m_exe_not_modelled
! @format 3
! @section 11
! @expect ok
! @description Linked_m_exe, which ABB's system module LINKEDM.sys of RobotWare 5 and 6 backups calls from its procedure Linked_m, is installed as that call shows it (no arguments), so the module checks; it is not modelled (exit 4) at the call (doc/rulings.md R-13-motset1).
! @exit 4
! @error Linked_m_exe 9:5
  PROC main()
    Linked_m_exe;
  ENDPROC
ENDMODULE
