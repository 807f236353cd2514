MODULE procedure_late_bound_unclosed
! @section 4.6
! @expect syntax-error 7:15
! @description A late-bound procedure name is closed by a second '%'.
  VAR num x;
  PROC main()
    % "proc1" x;
  ENDPROC
ENDMODULE
