MODULE declaration_variable_without
! @format 2
! @section 2.16
! @expect ok
! @description Table of section 2.16, row variable without initialisation: legal for value, non-value and semi-value types, also as arrays and routine data.
  VAR num n;
  VAR iodev dev;
  VAR signaldi di1;
  VAR iodev devs{2};
  VAR signaldi inputs{3};
  PROC main()
    VAR iodev logfile;
    VAR signaldi local_di;
  ENDPROC
ENDMODULE
