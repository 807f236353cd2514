MODULE tpwrite_bool
! @format 3
! @section 13
! @expect ok
! @description TPWrite \Bool writes TRUE or FALSE after the text.
! @output flag=TRUE
! @output flag=FALSE
! @exit 0
  PROC main()
    VAR bool flag := TRUE;
    TPWrite "flag=" \Bool:=flag;
    TPWrite "flag=" \Bool:=NOT flag;
  ENDPROC
ENDMODULE
