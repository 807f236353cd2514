MODULE served_at_statement
! @format 3
! @section 8
! @expect ok
! @statement-time 0.1
! @description An interrupt is served when the next statement is entered (chapter 8): with 0.1 s a statement, the timer ordered at 0.2 s (the second statement) is due at 0.45 s, during the statement that adds a1; its trap runs when the next statement (adding b1) is entered at 0.5 s, never inside a statement.
! @output a1 T b1 a2 b2 a3 b3
  VAR intnum t;
  VAR string log := "";
  TRAP tick
    log := log + " T";
  ENDTRAP
  PROC main()
    CONNECT t WITH tick;
    ITimer \Single, 0.25, t;
    FOR i FROM 1 TO 3 DO
      log := log + " a" + NumToStr(i, 0);
      log := log + " b" + NumToStr(i, 0);
    ENDFOR
    TPWrite StrPart(log, 2, StrLen(log) - 1);
  ENDPROC
ENDMODULE
