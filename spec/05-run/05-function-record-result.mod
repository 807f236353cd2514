MODULE function_record_result
! @format 3
! @section 5.5
! @expect ok
! @description A function may return a value of any value type (section 5.5), here a pos; its components are used directly.
! @output 4
! @output 6
! @exit 0
  FUNC pos double(pos p)
    RETURN 2 * p;
  ENDFUNC
  PROC main()
    VAR pos r;
    r := double([2, 3, 4]);
    TPWrite "" \Num:=r.x;
    TPWrite "" \Num:=r.y;
  ENDPROC
ENDMODULE
