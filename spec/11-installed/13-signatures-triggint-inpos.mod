MODULE sig_triggint_inpos
! @format 2
! @section 4.6
! @section 13
! @expect semantic-error 11:30
! @description TriggInt takes TriggData, Distance, \Start or \Time, and Interrupt (ABB: TriggInt TriggData Distance [\Start] | [\Time] Interrupt); it has no \Inpos (R-4.1-trigg1).
  VAR triggdata t;
  VAR intnum i;
  PROC main()
    TriggInt t, 10 \Start, i;
    TriggInt t, 10 \Start, i \Inpos:=1;
  ENDPROC
ENDMODULE
