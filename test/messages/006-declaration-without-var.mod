MODULE t
! @expect-message 3:7: syntax error: a name here can only be TASK, followed by VAR or PERS: a data declaration begins with VAR, PERS or CONST, after an optional LOCAL or TASK (§2.18); found the identifier counter
  num counter;
ENDMODULE
