MODULE function_value_in_statement
! @format 2
! @section 5.5
! @expect ok
! @description A function's value is used in an expression; its result type is checked like any other.
  VAR num n;
  VAR bool b;
  PROC main()
    n := veclen([3, 4, 0]);
    b := veclen([1, 0, 0]) > 0;
  ENDPROC
  FUNC num veclen(pos vector)
    RETURN vector.x * vector.x + vector.y * vector.y + vector.z * vector.z;
  ERROR
    RAISE;
  ENDFUNC
ENDMODULE
