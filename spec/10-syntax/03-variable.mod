MODULE variable
! @section 3.6
! @expect ok
! @description Entire variables, elements and components: the examples of sections 2.14, 3.6 and 4.5.
  VAR num row{3};
  VAR num column{3};
  VAR num mat{10, 10};
  VAR num i := 1;
  VAR num j := 1;
  VAR num x;
  VAR pos p1;
  VAR pos posarr{3};
  VAR pose pose1;
  PROC main()
    ! array assignment
    row := column;
    x := column{10};
    x := mat{i * 10, j};
    p1.x := 300;
    posarr{i}.y := x;
    x := pose1.trans.x;
  ENDPROC
ENDMODULE
