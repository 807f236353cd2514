MODULE reference_argument_non_value_var
! @format 2
! @section 2.16
! @section 5.2
! @expect ok
! @description Table of section 2.16, row argument, column non-value: legal for a var parameter (user routine) and a ref parameter (Present).
  VAR iodev logfile;
  PROC use(VAR iodev dev)
  ENDPROC
  PROC maybe(\VAR iodev dev)
    IF Present(dev) use dev;
  ENDPROC
  PROC main()
    use logfile;
    maybe \dev:=logfile;
  ENDPROC
ENDMODULE
