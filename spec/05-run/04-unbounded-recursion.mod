MODULE unbounded_recursion
! @format 3
! @section 5.4
! @section 1.4
! @expect ok
! @description A procedure that calls itself without end exhausts a resource (the call depth, or the steps): exit 3, after the output written before the recursion.
! @output start
! @exit 3
  PROC again(num n)
    again n + 1;
  ENDPROC
  PROC main()
    TPWrite "start";
    again 1;
  ENDPROC
ENDMODULE
