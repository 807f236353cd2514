MODULE cell
  VAR num conveyor;
ENDMODULE
