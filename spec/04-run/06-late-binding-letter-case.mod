MODULE late_binding_letter_case
! @format 3
! @section 4.6
! @section 2.3
! @expect ok
! @description Identifiers that differ only in letter case are the same (section 2.3), so the late-bound name "SHOW" finds the procedure show (reading: the name is looked up like an identifier).
! @output shown
! @exit 0
  PROC show()
    TPWrite "shown";
  ENDPROC
  PROC main()
    % "SHOW" %;
  ENDPROC
ENDMODULE
