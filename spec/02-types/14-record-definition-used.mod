MODULE record_definition_used
! @format 2
! @section 2.14
! @expect ok
! @description The record newtype of section 2.14, a variable of it, a component assignment and an aggregate.
  RECORD newtype
    num x;
  ENDRECORD
  VAR newtype t;
  PROC main()
    t.x := 300;
    t := [5];
  ENDPROC
ENDMODULE
