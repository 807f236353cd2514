MODULE busy_loop
! @format 3
! @section 13
! @section 4.19
! @expect ok
! @io io/basic.io
! @statement-time 0.001
! @description Every statement executed, and every new round of a loop, takes the statement time (@statement-time, doc/controller.md): a busy loop polling an input sees the stimulus change at 1 s, after about a thousand rounds.
! @output seen TRUE
  VAR num rounds := 0;
  PROC main()
    WHILE DInput(di1) = 0 DO
    ENDWHILE
    WHILE di1 = 1 DO
      rounds := rounds + 1;
    ENDWHILE
    TPWrite "seen " \Bool:=(rounds > 400 AND rounds < 600);
  ENDPROC
ENDMODULE
