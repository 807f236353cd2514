MODULE <ID>
! @section 9.2
! @section 2.9
! @expect ok
! @description <module name> ::= <identifier>, so <ID> may stand for it.
ENDMODULE
