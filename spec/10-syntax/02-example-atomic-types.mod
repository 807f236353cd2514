MODULE example_atomic_types
! @section 2.13
! @expect ok
! @description The num, dnum, bool and string examples of section 2.13.
  VAR num counter;
  VAR dnum value;
  VAR bool active;
  VAR string name;
  PROC main()
    counter := 250;
    value := 2E+43;
    active := TRUE;
    name := "John Smith";
  ENDPROC
ENDMODULE
