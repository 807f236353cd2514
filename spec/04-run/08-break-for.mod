MODULE break_for
! @format 3
! @section 4.8
! @section 4.18
! @expect ok
! @description BREAK ends a FOR loop early (section 4.18); the statements after it in the body are skipped.
! @output 1
! @output 2
! @output after
! @exit 0
  PROC main()
    FOR i FROM 1 TO 10 DO
      IF i = 3 BREAK;
      TPWrite "" \Num:=i;
    ENDFOR
    TPWrite "after";
  ENDPROC
ENDMODULE
