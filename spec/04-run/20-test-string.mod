MODULE test_string
! @format 3
! @section 4.20
! @expect ok
! @description The test expression may be of any value type (section 4.20): strings are compared for equality.
! @output green light
! @exit 0
  VAR string colour := "green";
  PROC main()
    TEST colour
    CASE "red", "amber":
      TPWrite "stop";
    CASE "green":
      TPWrite "green light";
    ENDTEST
  ENDPROC
ENDMODULE
