MODULE safediv_example
! @format 3
! @section 7.1
! @section 4.10
! @expect ok
! @description Section 7.1's safediv: the error handler of a function returns a value with RETURN, which becomes the value of the call (max_num declared as 1000).
! @output 5
! @output 1000
! @exit 0
  CONST num max_num := 1000;
  FUNC num safediv(num x, num y)
    RETURN x / y;
  ERROR
    IF ERRNO = ERR_DIVZERO THEN
      ! return max numeric value
      RETURN max_num;
    ENDIF
  ENDFUNC
  PROC main()
    TPWrite "" \Num:=safediv(10, 2);
    TPWrite "" \Num:=safediv(10, 0);
  ENDPROC
ENDMODULE
