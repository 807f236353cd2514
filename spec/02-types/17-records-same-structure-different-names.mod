MODULE records_same_structure_different
! @format 2
! @section 2.17
! @expect semantic-error 17:10
! @description Two record types with the same components but different names are not equal types; refused at the right-hand side.
  RECORD pair
    num a;
    num b;
  ENDRECORD
  RECORD couple
    num a;
    num b;
  ENDRECORD
  VAR pair p;
  VAR couple c;
  PROC main()
    p := c;
  ENDPROC
ENDMODULE
