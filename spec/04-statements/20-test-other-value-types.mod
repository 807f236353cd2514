MODULE test_other_value_types
! @format 2
! @section 4.20
! @expect ok
! @description The test expression may be of any value type: string, bool, an alias of num, a record.
  ALIAS num state;
  VAR string mode;
  VAR bool b;
  VAR state s;
  VAR num n;
  PROC main()
    TEST mode
    CASE "auto", "manual":
      n := 1;
    ENDTEST
    TEST b
    CASE TRUE:
      n := 2;
    ENDTEST
    TEST s
    CASE 1:
      n := 3;
    ENDTEST
  ENDPROC
ENDMODULE
