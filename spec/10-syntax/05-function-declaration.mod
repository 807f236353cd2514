MODULE function_declaration
! @section 5.5
! @expect ok
! @description The example of section 5.5, and a function with data declarations and an UNDO part.
  VAR num maxnum := 1E6;
  FUNC num veclen(pos vector)
    RETURN sqrt(quad(vector.x) + quad(vector.y) + quad(vector.z));
  ERROR
    IF ERRNO = ERR_OVERFLOW THEN
      RETURN maxnum;
    ENDIF
    ! propagate "unexpected" error
    RAISE;
  ENDFUNC
  FUNC bool f(\switch s)
    VAR bool b;
    b := Present(s);
    RETURN b;
  UNDO
    b := FALSE;
  ENDFUNC
ENDMODULE
