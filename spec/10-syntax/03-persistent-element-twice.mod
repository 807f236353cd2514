MODULE persistent_element_twice
! @section 3.7
! @expect syntax-error 7:10
! @description A persistent element is indexed once, with an index list.
  PERS num pa{2, 2} := [[1, 2], [3, 4]];
  PROC main()
    pa{1}{2} := 0;
  ENDPROC
ENDMODULE
