MODULE for_single_iteration
! @format 3
! @section 4.18
! @expect ok
! @description FROM and TO equal: the body runs once.
! @output 4
! @output after
! @exit 0
  PROC main()
    FOR i FROM 4 TO 4 DO
      TPWrite "" \Num:=i;
    ENDFOR
    TPWrite "after";
  ENDPROC
ENDMODULE
