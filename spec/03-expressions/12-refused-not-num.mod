MODULE refused_not_num
! @format 2
! @section 3.12
! @expect semantic-error 9:10
! @description NOT takes a bool operand; refused at the operator.
  VAR num n;
  VAR bool r;
  PROC main()
    r := NOT n;
  ENDPROC
ENDMODULE
