MODULE function_without_return_place
! @format 3
! @section 5.5
! @section 12
! @expect ok
! @description A function that reaches its end has ended, so ERR_FNCNORET is raised at its call, in the caller's statement (doc/rulings.md R-5.5); the function ran to its end and was not abandoned, so its UNDO handler does not run.
! @output in f
! @exit 1
! @error ERR_FNCNORET 17:5
  FUNC num f()
    TPWrite "in f";
  UNDO
    TPWrite "wrong: f undo";
  ENDFUNC
  PROC main()
    VAR num x;
    x := f() + 1;
    TPWrite "wrong";
  ENDPROC
ENDMODULE
