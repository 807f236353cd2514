let module_declaration _ = failwith "Printer: not written yet"
let expression _ = failwith "Printer: not written yet"
let statement _ = failwith "Printer: not written yet"
