MODULE late_binding
! @format 2
! @section 4.6
! @expect ok
! @description Late-bound calls (section 4.6): the procedure name is a string expression, and the call is checked when it runs.
  VAR num product_id := 2;
  VAR string procname{3} := ["proc1", "proc2", "proc3"];
  VAR num x;
  VAR num y;
  VAR num z;
  PROC main()
    % procname{product_id} % x, y, z;
    % "proc" + "2" % x, y, z;
    % procname{1} % "not", "checked", TRUE;
  ENDPROC
  PROC proc1(num a, num b, num c)
  ENDPROC
  PROC proc2(num a, num b, num c)
  ENDPROC
  PROC proc3(num a, num b, num c)
  ENDPROC
ENDMODULE
