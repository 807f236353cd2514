MODULE installed_procedure_exclusive
! @format 2
! @section 4.6
! @expect semantic-error 8:28
! @description TPWrite's optional Num and Bool are mutually exclusive; the second is refused at its backslash.
  VAR num n;
  PROC main()
    TPWrite "n = " \Num:=n \Bool:=TRUE;
  ENDPROC
ENDMODULE
