MODULE rulings_literal_once
! @format 3
! @section 2.13
! @section 2.5
! @expect ok
! @description R-2.13-a: a num literal is rounded once, from its exact decimal value, to single precision: 1.00000005960464477539062500000000001 lies just above the midpoint between the singles 1 and 1 + 2^-23, so it is 1 + 2^-23 (rounding to double first would give 1); subnormal singles are kept (1.4E-45, 7.1E-46) and 7.0E-46 is 0.
! @output above the midpoint = 1 FALSE
! @output above the midpoint = 1 + 2^-23 TRUE
! @output 1.4E-45 > 0 TRUE
! @output 7.1E-46 = 1.4E-45 TRUE
! @output 7.0E-46 = 0 TRUE
! @output largest single TRUE
! @exit 0
  PROC main()
    VAR num x := 1.00000005960464477539062500000000001;
    VAR num tiny := 1.4E-45;
    VAR num above := 7.1E-46;
    VAR num below := 7.0E-46;
    VAR num top := 3.4028234663852886E38;
    TPWrite "above the midpoint = 1 " \Bool:=x = 1;
    TPWrite "above the midpoint = 1 + 2^-23 " \Bool:=x = 1.00000011920928955078125;
    TPWrite "1.4E-45 > 0 " \Bool:=tiny > 0;
    TPWrite "7.1E-46 = 1.4E-45 " \Bool:=above = tiny;
    TPWrite "7.0E-46 = 0 " \Bool:=below = 0;
    TPWrite "largest single " \Bool:=top = 3.4028235E38;
  ENDPROC
ENDMODULE
