MODULE bool_literals
! @section 2.6
! @expect ok
! @description <bool literal> ::= TRUE | FALSE, in any letter case.
  VAR bool b;
  PROC main()
    b := TRUE;
    b := FALSE;
    b := true;
    b := False;
  ENDPROC
ENDMODULE
