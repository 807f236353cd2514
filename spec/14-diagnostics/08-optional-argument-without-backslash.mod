MODULE optional_argument_no_backslash
! @format 2
! @section 4.6
! @section 5.2
! @expect semantic-error 9:21
! @description TPWrite "a = ", a; passes a second argument where TPWrite takes one required argument: the optional \Num is written with its backslash (the hint: \Num:=a).
  PROC main()
    VAR num a := 1;
    TPWrite "a = ", a;
  ENDPROC
ENDMODULE
