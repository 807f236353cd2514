MODULE procedure_argument_forms
! @section 4.6
! @expect ok
! @description Every form of <first procedure argument> and <procedure argument>, with and without commas.
  VAR num x;
  PROC main(\num o)
    p;
    p <ARG>;
    p \a;
    p \a ? o;
    p \a ? <VAR>;
    p 1, name := 2, <ID> := 3;
    p 1 \a \b := 2 \c ? o;
    p 1, \a, \b := 2, \c ? o, <ARG>;
    p <EXP>, x;
  ENDPROC
ENDMODULE
