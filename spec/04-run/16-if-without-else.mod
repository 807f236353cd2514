MODULE if_without_else
! @format 3
! @section 4.16
! @expect ok
! @description When no condition is true and there is no ELSE, no statement list runs (section 4.16).
! @output after
! @exit 0
  VAR num a := 1;
  PROC main()
    IF a > 5 THEN
      TPWrite "wrong 1";
    ELSEIF a > 3 THEN
      TPWrite "wrong 2";
    ENDIF
    TPWrite "after";
  ENDPROC
ENDMODULE
