MODULE compact_if_statement
! @section 4.17
! @expect ok
! @description <compact if statement> ::= IF <conditional expression> ( <simple statement> | <SMT> ).
  VAR num reg1;
  VAR bool b;
  VAR intnum ino;
  PROC main()
    IF reg1=1 proc1;
    IF reg1 = 1 reg1 := 2;
    IF b GOTO next;
    IF b RETURN;
    IF b RAISE 10;
    IF b EXIT;
    IF b CONNECT ino WITH t;
    IF b <SMT>
    next:
  ENDPROC
ENDMODULE
