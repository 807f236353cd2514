MODULE aggregate
! @section 3.10
! @expect ok
! @description The aggregates of sections 2.14 and 3.10.
  VAR num x;
  VAR num y;
  VAR num z;
  VAR num a;
  VAR num b;
  VAR num c;
  VAR num depth;
  VAR pos p;
  VAR pos p1;
  VAR string names{3};
  VAR pos ps{2};
  VAR num m{2, 3};
  PROC main()
    p := [x, y, 2*x];
    names := ["john", "eric", "lisa"];
    ps := [[100, 100, 0], [0, 0, z]];
    m := [[1, 2, 3], [a, b, c]];
    ! Aggregate type pos - determined by p1
    p1 := [1, -100, 12];
    p := [300, 500, depth];
  ENDPROC
ENDMODULE
