MODULE late_binding_aggregate
! @format 3
! @section 4.6
! @section 3.10
! @expect ok
! @description An aggregate has the type its context gives it (section 3.10): passed by a late-bound call it takes its parameter's type when its members fit it; an aggregate of another structure raises ERR_CALLPROC.
! @output pos=[1,2,3]
! @output sum=6
! @output two members for a pos: 
! @output callproc
! @exit 0
  PROC show_pos(pos q)
    TPWrite "pos=" \Pos:=q;
  ENDPROC
  PROC add(num list{*})
    VAR num s;
    FOR i FROM 1 TO Dim(list, 1) DO
      s := s + list{i};
    ENDFOR
    TPWrite "sum=" \Num:=s;
  ENDPROC
  PROC main()
    % "show_pos" % [1, 2, 3];
    % "add" % [1, 2, 3];
    TPWrite "two members for a pos: ";
    % "show_pos" % [1, 2];
  ERROR
    IF ERRNO = ERR_CALLPROC THEN
      TPWrite "callproc";
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
