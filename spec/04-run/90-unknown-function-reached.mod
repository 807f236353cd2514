MODULE unknown_function_reached
! @format 3
! @section 3.11
! @section 13
! @options allow-unknown
! @expect ok
! @description With --allow-unknown a call of a function neither declared nor installed is a warning; evaluating it is ERR_REFUNKFUN (ch. 12).
! @exit 1
! @error ERR_REFUNKFUN 13:5
  VAR num x;
  PROC main()
    x := 1;
    x := NoSuchFunction(x) + 1;
  ENDPROC
ENDMODULE
