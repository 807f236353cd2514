MODULE isvar_ispers_use
! @format 3
! @section 11
! @section 5.2
! @expect ok
! @description IsVar and IsPers (chapter 11) look through the alias of an inout parameter: an element of a variable array is a variable, a component of a persistent is a persistent, and the answer holds in a function too.
! @output element: TRUE FALSE
! @output component: FALSE TRUE
! @exit 0
  VAR num a{2};
  PERS pos p := [0, 0, 0];
  FUNC string kind(INOUT num x)
    RETURN ValToStr(IsVar(x)) + " " + ValToStr(IsPers(x));
  ENDFUNC
  PROC main()
    TPWrite "element: " + kind(a{2});
    TPWrite "component: " + kind(p.y);
  ENDPROC
ENDMODULE
