MODULE label_hides_module_data_use
! @format 2
! @section 4.4
! @expect semantic-error 9:5
! @description Within the routine that declares the label next, next names the label: using it as a variable is refused at the name.
  VAR num next;
  PROC main()
    next:
    next := 1;
  ENDPROC
ENDMODULE
