MODULE placeholder_argument
! @format 2
! @section 3.11
! @section 4.6
! @section 2.9
! @expect ok
! @description <EXP> stands for a whole expression (a procedure argument, an initial value) and <ARG> for an argument, without a semantic error.
  VAR num x;
  PROC main()
    show <EXP>, 0.5;
    show x, <ARG>;
    x := <EXP>;
  ENDPROC
  PROC show(num a, num b)
  ENDPROC
ENDMODULE
