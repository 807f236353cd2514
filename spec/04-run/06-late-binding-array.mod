MODULE late_binding_array
! @format 3
! @section 4.6
! @expect ok
! @description Section 4.6's late binding, example 2: the name comes from an array of strings; every call is bound when it runs, and a var argument is passed by alias.
! @output proc1
! @output proc2
! @output proc3
! @output x=3
! @exit 0
  VAR string procname{3} := ["proc1", "proc2", "proc3"];
  VAR num x;
  PROC main()
    FOR product_id FROM 1 TO 3 DO
      % procname{product_id} % x;
    ENDFOR
    TPWrite "x=" \Num:=x;
  ENDPROC
  PROC proc1(VAR num a)
    TPWrite "proc1";
    Incr a;
  ENDPROC
  PROC proc2(VAR num a)
    TPWrite "proc2";
    Incr a;
  ENDPROC
  PROC proc3(VAR num a)
    TPWrite "proc3";
    Incr a;
  ENDPROC
ENDMODULE
