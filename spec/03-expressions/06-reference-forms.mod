MODULE reference_forms
! @format 2
! @section 3.6
! @section 4.5
! @expect ok
! @description Entire variables, elements and components, and combinations (section 4.5's assignment examples).
  VAR num count;
  VAR pos home;
  VAR num x;
  VAR num matrix{4, 4};
  VAR num temp;
  VAR num i := 1;
  VAR num j := 2;
  VAR pos posarr{5};
  VAR num column{10};
  PROC main()
    count := count + 1;
    home.x := x * 2;
    matrix{i, j} := temp;
    posarr{i}.y := x;
    x := column{10};
    x := matrix{i * 2, j};
  ENDPROC
ENDMODULE
