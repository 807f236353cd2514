MODULE moveextj_axis
! @format 3
! @section 13
! @expect ok
! @statement-time 0
! @description MoveExtJ to a position of an external axis (eax_a 100): rapid-sem's robots have no external axes and does not model them, so the run ends as unsupported at the instruction (exit 4, R-4.1-n), after what came before it.
! @output before
! @exit 4
  CONST jointtarget ext_a := [[0,0,0,0,0,0],[100,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    TPWrite "before";
    MoveExtJ ext_a, v1000, fine;
    TPWrite "after";
  ENDPROC
ENDMODULE
