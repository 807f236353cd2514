MODULE refused_mod_non_integer_constant
! @format 2
! @section 3.12
! @expect semantic-error 9:10
! @description Note (b) of section 3.12: MOD operands must represent integer values; the constant 7.5 is refused at the start of the operation.
  VAR num n;
  VAR num r;
  PROC main()
    r := 7.5 MOD n;
  ENDPROC
ENDMODULE
