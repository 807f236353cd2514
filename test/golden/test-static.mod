MODULE StaticTest
  ! AssertEqual compares numbers: a string is a static error, before any test runs.
  PROC test_types()
    AssertEqual "three", 3;
  ENDPROC
ENDMODULE
