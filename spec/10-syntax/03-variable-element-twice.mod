MODULE variable_element_twice
! @section 3.6
! @expect syntax-error 8:14
! @description An element is indexed once, with an index list: a{1}{2} is not derivable (a{1, 2} is).
  VAR num x;
  VAR num a{2, 2};
  PROC main()
    x := a{1}{2};
  ENDPROC
ENDMODULE
