MODULE example_record_types
! @section 2.14
! @expect ok
! @description The pos, orient and pose examples of section 2.14 (the pose variable, also named p1 there, renamed ps1 to share one module).
  VAR pos p1;
  VAR pos p2;
  VAR orient o1;
  VAR pose ps1;
  VAR num a1;
  VAR num b1;
  VAR num g1;
  VAR pos homepos;
  PROC main()
    p1 := [10, 10, 55.7];
    p1.z := p1.z + 250;
    p1 := p1 + p2;
    o1 := [1, 0, 0, 0];
    o1.q1 := -1;
    o1 := Euler(a1,b1,g1);
    ps1 := [[100, 100, 0], o1];
    ps1.trans := homepos;
  ENDPROC
ENDMODULE
