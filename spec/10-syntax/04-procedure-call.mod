MODULE procedure_call
! @section 4.6
! @expect ok
! @description The procedure calls of section 4.6: early and late binding, named, switch and optional arguments.
  VAR num x;
  VAR num y;
  VAR num z;
  VAR num product_id := 1;
  VAR string procname {3} := ["proc1", "proc2", "proc3"];
  VAR num t1;
  VAR num pos2;
  VAR num mv;
  VAR num dest;
  PROC main()
    proc1 x, y, z;
    % "proc" + NumToStr(product_id, 0) % x, y, z;
    % procname{product_id} % x, y, z;
    move t1, pos2, mv;
    move tool := t1, dest := pos2, movedata := mv;
    move \reltool, t1, dest, mv;
    move \reltool, t1, dest, mv \speed := 100;
    move \reltool, t1, dest, mv \time := 20;
    p(1);
  ENDPROC
ENDMODULE
