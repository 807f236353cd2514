MODULE if_conditions
! @format 2
! @section 4.16
! @section 3.4
! @expect ok
! @description Section 4.16's example: conditions of type bool in IF and ELSEIF, also of an alias of bool and function results.
  ALIAS bool flag;
  VAR num counter;
  VAR flag ready;
  PROC main()
    IF counter > 100 THEN
      counter := 100;
    ELSEIF counter < 0 THEN
      counter := 0;
    ELSEIF ready THEN
      counter := 1;
    ELSEIF positive(counter) THEN
      counter := 2;
    ELSE
      counter := counter + 1;
    ENDIF
  ENDPROC
  FUNC bool positive(num x)
    RETURN x > 0;
  ENDFUNC
ENDMODULE
