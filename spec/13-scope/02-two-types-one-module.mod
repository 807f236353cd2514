MODULE two_types_one_module
! @format 2
! @section 2.12
! @expect semantic-error 9:13
! @description A record and an alias of one module may not share a name; the second is refused at its name.
  RECORD level
    num value;
  ENDRECORD
  ALIAS num level;
ENDMODULE
