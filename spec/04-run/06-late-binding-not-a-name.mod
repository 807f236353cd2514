MODULE late_binding_not_a_name
! @format 3
! @section 4.6
! @section 12
! @expect ok
! @description Ruling R-4.6-name1: a late-bound string that is no procedure name (neither an identifier of section 2.3 nor "name1:name2" of two) raises ERR_CALLPROC, the call's "syntax" error of chapter 12; a procedure name that denotes nothing raises ERR_REFUNKPRC, the reference to an unknown procedure; CallByVar binds its name the same way.
! @output [1 two] ERR_CALLPROC
! @output [] ERR_CALLPROC
! @output [a:b:c] ERR_CALLPROC
! @output [late_binding_not_a_name:] ERR_CALLPROC
! @output [ proc1] ERR_CALLPROC
! @output [IF] ERR_CALLPROC
! @output [abcdefghijabcdefghijabcdefghijabc] ERR_CALLPROC
! @output [no_such_proc] ERR_REFUNKPRC
! @output [no_module:proc1] ERR_REFUNKPRC
! @output [proc1] called
! @output CallByVar [1 two] ERR_CALLPROC
! @output CallByVar [proc] ERR_REFUNKPRC
! @exit 0
  VAR string names{10} := ["1 two", "", "a:b:c", "late_binding_not_a_name:", " proc1", "IF",
                           "abcdefghijabcdefghijabcdefghijabc", "no_such_proc", "no_module:proc1", "proc1"];
  VAR num i;
  FUNC string ErrName(num n)
    IF n = ERR_CALLPROC RETURN "ERR_CALLPROC";
    IF n = ERR_REFUNKPRC RETURN "ERR_REFUNKPRC";
    RETURN "another error";
  ENDFUNC
  PROC proc1()
    TPWrite "[proc1] called";
  ENDPROC
  PROC main()
    FOR k FROM 1 TO 10 DO
      i := k;
      % names{k} %;
    ENDFOR
    i := 11;
    CallByVar "1 two", 1;
    i := 12;
    CallByVar "proc", 2;
  ERROR
    IF i <= 10 THEN
      TPWrite "[" + names{i} + "] " + ErrName(ERRNO);
    ELSEIF i = 11 THEN
      TPWrite "CallByVar [1 two] " + ErrName(ERRNO);
    ELSE
      TPWrite "CallByVar [proc] " + ErrName(ERRNO);
    ENDIF
    TRYNEXT;
  ENDPROC
ENDMODULE
