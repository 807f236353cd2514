MODULE alias_of_record
! @format 2
! @section 2.15
! @expect ok
! @description An alias of a user-defined record is a value type like its base; aggregates of the base type initialise it.
  RECORD pair
    num first;
    num second;
  ENDRECORD
  ALIAS pair couple;
  VAR couple c := [1, 2];
  PROC main()
    c.second := c.first;
  ENDPROC
ENDMODULE
