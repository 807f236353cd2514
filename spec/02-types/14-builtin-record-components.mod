MODULE builtin_record_components
! @format 2
! @section 2.14
! @expect ok
! @description The components of pos (x, y, z), orient (q1-q4) and pose (trans, rot), and the examples of section 2.14.
  VAR pos p1;
  VAR pos p2;
  VAR orient o1;
  VAR pose pp;
  VAR pos homepos;
  PROC main()
    p1 := [10, 10, 55.7];
    p1.z := p1.z + 250;
    p1 := p1 + p2;
    o1 := [1, 0, 0, 0];
    o1.q1 := -1;
    o1.q4 := o1.q2 + o1.q3;
    pp := [[100, 100, 0], o1];
    pp.trans := homepos;
    pp.rot.q1 := pp.trans.x;
  ENDPROC
ENDMODULE
