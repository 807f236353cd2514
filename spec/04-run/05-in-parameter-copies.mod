MODULE in_parameter_copies
! @format 3
! @section 5.2
! @section 4.5
! @expect ok
! @description An in parameter is a copy of its argument: a routine that changes its parameter, passes it by reference to a routine that changes it, or changes the module data given as its argument, leaves the caller's data as they were and reads its own copy; a routine that only reads its parameter (components, an aggregate made of it, routine data initialised from it) reads the argument's value.
! @output p.x=1 after a write
! @output p.x=1 after an INOUT call
! @output read 1 of g, g.x=100
! @output read 3
! @output read 1 after an aggregate
! @output read 1 after routine data
! @output p.x=1 q.x=5
! @exit 0
  VAR pos g := [1, 0, 0];

  PROC writes(pos v)
    v.x := 9;
  ENDPROC

  PROC bump(INOUT pos w)
    w.x := w.x + 10;
  ENDPROC

  PROC passes(pos v)
    bump v;
  ENDPROC

  FUNC num reads_after_global(pos v)
    g.x := 100;
    RETURN v.x;
  ENDFUNC

  FUNC num sum_xy(pos v)
    RETURN v.x + v.y;
  ENDFUNC

  FUNC num through_aggregate(pos v)
    VAR pos both{2};
    both := [v, v];
    both{1}.x := 50;
    RETURN v.x;
  ENDFUNC

  FUNC num through_data(pos v)
    VAR pos kept;
    kept := v;
    kept.x := 60;
    RETURN v.x;
  ENDFUNC

  FUNC pos translated(pos v)
    VAR pos q;
    q := v;
    q.x := q.x + 4;
    RETURN q;
  ENDFUNC

  PROC main()
    VAR pos p := [1, 2, 0];
    VAR pos q;
    VAR num n;
    writes p;
    TPWrite "p.x=" + NumToStr(p.x, 0) + " after a write";
    passes p;
    TPWrite "p.x=" + NumToStr(p.x, 0) + " after an INOUT call";
    n := reads_after_global(g);
    TPWrite "read " + NumToStr(n, 0) + " of g, g.x=" + NumToStr(g.x, 0);
    TPWrite "read " + NumToStr(sum_xy(p), 0);
    TPWrite "read " + NumToStr(through_aggregate(p), 0) + " after an aggregate";
    TPWrite "read " + NumToStr(through_data(p), 0) + " after routine data";
    q := translated(p);
    TPWrite "p.x=" + NumToStr(p.x, 0) + " q.x=" + NumToStr(q.x, 0);
  ENDPROC
ENDMODULE
