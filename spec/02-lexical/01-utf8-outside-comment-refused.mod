MODULE utf8_outside_comment_refused
! @section 2.1
! @expect lexical-error 5:11
! @description A character outside ISO 8859-1 (Greek capital delta) may appear only in comments and string literals.
  VAR num Δx;
ENDMODULE
