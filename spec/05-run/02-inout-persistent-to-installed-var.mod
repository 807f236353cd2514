MODULE inout_pers_to_installed_var
! @format 3
! @section 5.2
! @section 12
! @expect ok
! @description Section 5.2's table, cell "parameter inout pers" to a var parameter, when the var parameter is an installed routine's (ITimer's interrupt identity): the same execution error as for a RAPID routine's, ERR_ARGNOTVAR (chapter 12) at the call. Found by the fuzzer's CONNECT scenarios (doc/fuzz-campaign.md), where the closure engine raised ERR_UNKINO instead.
! @output in arm
! @exit 1
! @error ERR_ARGNOTVAR 16:5
  PERS intnum p := 0;
  TRAP never
    TPWrite "wrong";
  ENDTRAP
  PROC arm(INOUT intnum x)
    TPWrite "in arm";
    ITimer \Single, 0.01, x;
  ENDPROC
  PROC main()
    arm p;
  ENDPROC
ENDMODULE
