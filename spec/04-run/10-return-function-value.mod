MODULE return_function_value
! @format 3
! @section 4.10
! @section 5.5
! @expect ok
! @description Section 4.10's abs_value: a function may hold several RETURN statements; the one executed gives the value.
! @output 5
! @output 3
! @exit 0
  FUNC num abs_value(num value)
    IF value < 0 THEN
      RETURN -value;
    ELSE
      RETURN value;
    ENDIF
  ENDFUNC
  PROC main()
    TPWrite "" \Num:=abs_value(-5);
    TPWrite "" \Num:=abs_value(3);
  ENDPROC
ENDMODULE
