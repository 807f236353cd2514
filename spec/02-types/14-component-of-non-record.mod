MODULE component_of_non_record
! @format 2
! @section 2.14
! @expect semantic-error 8:7
! @description A num has no components: a component reference on it is refused at the component name.
  VAR num n;
  PROC main()
    n.x := 1;
  ENDPROC
ENDMODULE
