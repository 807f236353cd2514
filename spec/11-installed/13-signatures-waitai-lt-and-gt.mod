MODULE sig_waitai_lt
! @format 2
! @section 5.2
! @section 13
! @expect semantic-error 9:27
! @description WaitAI: \LT and \GT are alternatives (ABB: [\LT] | [\GT]); giving both is refused at the second's backslash.
  VAR signalai aiPressure;
  PROC main()
    WaitAI aiPressure \LT \GT, 4.5;
  ENDPROC
ENDMODULE
