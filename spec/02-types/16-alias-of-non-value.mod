MODULE alias_of_non_value
! @format 2
! @section 2.16
! @section 2.15
! @expect semantic-error 9:7
! @description An alias of a non-value type is a non-value type: no variable with initialisation of it.
  ALIAS iodev channel;
  VAR channel ch1;
  VAR channel ch2 := <EXP>;
ENDMODULE
