MODULE conditional_arguments_exclusive
! @format 2
! @section 3.11
! @expect ok
! @description Section 3.11: check(\on ? high \off ? low) with the caller's mutually exclusive switches high and low.
  FUNC bool relay(\switch high | switch low)
    RETURN check(\on ? high \off ? low);
  ENDFUNC

  FUNC bool check(\switch on | switch off)
    RETURN Present(on);
  ENDFUNC
ENDMODULE
