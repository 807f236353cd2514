MODULE routine_data_num_and_dnum
! @format 3
! @section 2.21
! @section 4.5
! @section 4.18
! @section 3.12
! @section 5.2
! @expect ok
! @description Routine data of type num and dnum, and FOR variables, in the ways a routine uses them: each activation of a recursive function has its own (acc and i below); routine data changed through Incr, an INOUT parameter and a late-bound call by reference keeps what they wrote; comparisons with the literal on either side; a num product rounded to single (4097 * 4097 is 16785408); a dnum product exact; an infinite product is ERR_OVERFLOW and leaves the variable as it was. Routine data of a record type has its initial value when the statement that first assigns it reads it, or when the error handler reads it after that statement failed; routine data of a signal type is the unconnected signal when its routine's first statement assigns it, which is then ERR_NO_ALIASIO_DEF (§2.16).
! @output sum 220 385
! @output incr 3 inout 13 late 23
! @output while 4.5 3
! @output 16785408 16785409
! @output handled 1120
! @output kept 1E+30
! @output signal 1117
! @output pos [1,0,5] [0,0,0] [5,0,0]
! @exit 0
  FUNC num sumdown(num n)
    VAR num acc := 0;
    FOR i FROM 1 TO n DO
      acc := acc + i;
    ENDFOR
    IF n > 1 acc := acc + sumdown(n - 1);
    RETURN acc;
  ENDFUNC
  FUNC pos from_itself()
    VAR pos q;
    q := [q.x + 1, q.y, 5];
    RETURN q;
  ENDFUNC
  FUNC pos divided(num d)
    VAR pos q;
    q := [10 / d, 0, 0];
    RETURN q;
  ERROR
    RETURN q;
  ENDFUNC
  PROC set_signal()
    VAR signaldo d;
    d := 1;
    TPWrite "set";
  ENDPROC
  PROC add_ten(INOUT num v)
    v := v + 10;
  ENDPROC
  PROC main()
    VAR num k := 1;
    VAR num w := 3;
    VAR num u := 3;
    VAR num a := 0;
    VAR num b := 4;
    VAR num steps := 0;
    VAR num m := 4097;
    VAR dnum dm := 4097;
    VAR num o := 1E+30;
    TPWrite "sum " + NumToStr(sumdown(10), 0) + " " + NumToStr(sumdown(10) + sumdown(9) + sumdown(1) - 1, 0);
    Incr k;
    Incr k;
    add_ten w;
    %"add_ten"% u;
    %"add_ten"% u;
    TPWrite "incr " + NumToStr(k, 0) + " inout " + NumToStr(w, 0) + " late " + NumToStr(u, 0);
    WHILE a < b DO
      a := a + 1.5;
      IF 10 > steps steps := steps + 1;
    ENDWHILE
    TPWrite "while " + NumToStr(a, 1) + " " + NumToStr(steps, 0);
    m := m * m;
    dm := dm * dm;
    TPWrite NumToStr(m, 0) + " " + DnumToStr(dm, 0);
    o := o * o;
    TPWrite "kept " + NumToStr(o, 0\Exp);
    set_signal;
    TPWrite "pos " + ValToStr(from_itself()) + " " + ValToStr(divided(0)) + " " + ValToStr(divided(2));
  ERROR
    IF ERRNO = 1117 THEN
      TPWrite "signal " \Num:=ERRNO;
    ELSE
      TPWrite "handled " \Num:=ERRNO;
    ENDIF
    TRYNEXT;
  ENDPROC
ENDMODULE
