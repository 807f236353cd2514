MODULE aggregate_manual_table
! @format 2
! @section 3.10
! @expect ok
! @description The aggregates of section 3.10's table, each typed by the variable it is assigned to.
  VAR num x;
  VAR num y;
  VAR num z;
  VAR num a;
  VAR num b;
  VAR num c;
  VAR pos p;
  VAR string names{3};
  VAR pos points{2};
  VAR num mat{2, 3};
  PROC main()
    p := [x, y, 2*x];
    names := ["john", "eric", "lisa"];
    points := [[100, 100, 0], [0, 0, z]];
    mat := [[1, 2, 3], [a, b, c]];
  ENDPROC
ENDMODULE
