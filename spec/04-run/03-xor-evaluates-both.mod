MODULE xor_evaluates_both
! @format 3
! @section 3.1
! @section 3.12
! @expect ok
! @description Only AND and OR are optimised (section 3.1 names those two): XOR always evaluates its right operand, since its result depends on both.
! @output side
! @output xor=FALSE
! @exit 0
  VAR bool yes := TRUE;
  FUNC bool side()
    TPWrite "side";
    RETURN TRUE;
  ENDFUNC
  PROC main()
    TPWrite "xor=" \Bool:=yes XOR side();
  ENDPROC
ENDMODULE
