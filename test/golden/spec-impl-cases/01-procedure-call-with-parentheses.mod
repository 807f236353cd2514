MODULE procedure_call_with_parentheses
! @section 4.6
! @expect syntax-error 11:16
! @description A procedure called with its arguments in parentheses: "(" begins a parenthesised first argument, and the comma after "Bob" is where it stops being one. The hint: write greet "Bob", 2;
  PROC greet(string name, num n)
    TPWrite name;
  ENDPROC

  PROC main()
    ! the mistake
    greet("Bob", 2);
  ENDPROC
ENDMODULE
