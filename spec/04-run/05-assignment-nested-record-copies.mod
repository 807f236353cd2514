MODULE nested_record_copies
! @format 3
! @section 4.5
! @section 2.14
! @expect ok
! @description Copying a record copies its record components too: after q := p, p.trans.x := 100 leaves q.trans.x at 1.
! @output p=100
! @output q=1
! @exit 0
  PROC main()
    VAR pose p := [[1, 2, 3], [1, 0, 0, 0]];
    VAR pose q;
    q := p;
    p.trans.x := 100;
    TPWrite "p=" \Num:=p.trans.x;
    TPWrite "q=" \Num:=q.trans.x;
  ENDPROC
ENDMODULE
