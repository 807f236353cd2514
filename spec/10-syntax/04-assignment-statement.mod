MODULE assignment_statement
! @section 4.5
! @expect ok
! @description The examples of section 4.5.
  VAR num count;
  VAR pos home;
  VAR num x;
  VAR num matrix{2, 2};
  VAR num i := 1;
  VAR num j := 1;
  VAR num temp;
  VAR pos posarr{2};
  PROC main()
    count := count +1;
    home.x := x * sin(30);
    matrix{i, j} := temp;
    posarr{i}.y := x;
    <VAR> := temp + 5;
  ENDPROC
ENDMODULE
