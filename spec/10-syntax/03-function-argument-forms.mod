MODULE function_argument_forms
! @section 3.11
! @expect ok
! @description Every form of <first function argument> and <function argument>, with and without commas.
  VAR num x;
  VAR num a;
  PROC p(\num o)
    x := f(\sw);
    x := f(\sw ? o);
    x := f(1, 2, name := 3);
    x := f(1 \sw \v := 2 \c ? o);
    x := f(1, \sw, \v := 2, \c ? o, 4);
    x := f(a{1}, -a, (a));
  ENDPROC
ENDMODULE
