MODULE return_from_nested_loops
! @format 3
! @section 4.10
! @expect ok
! @description RETURN may stand at any depth of compound statements (section 4.10): from inside two loops it ends the function with its value.
! @output found=6
! @exit 0
  FUNC num first_product_over(num limit)
    FOR i FROM 1 TO 5 DO
      FOR j FROM 1 TO 5 DO
        IF i * j > limit RETURN i * j;
      ENDFOR
    ENDFOR
    RETURN 0;
  ENDFUNC
  PROC main()
    TPWrite "found=" \Num:=first_product_over(5);
  ENDPROC
ENDMODULE
