MODULE t
! @expect-message 4:3: syntax error: expected a record component, a data type followed by a name: a record has at least one component (§2.14); found ENDRECORD
  RECORD r
  ENDRECORD
ENDMODULE
