MODULE t
! @expect-message 4:1: syntax error: expected the end of the file after ENDMODULE: a file holds one module (§9.2), and comments are list elements only, not allowed after it (§2.10); found a comment
ENDMODULE
! end of file
