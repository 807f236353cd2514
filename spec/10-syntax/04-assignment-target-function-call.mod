MODULE assignment_target_function_call
! @section 4.5
! @expect syntax-error 7:10
! @description A function call is not an assignment target (f(1) reads as a call of procedure f with argument (1)).
  VAR num x;
  PROC main()
    f(1) := 2;
  ENDPROC
ENDMODULE
