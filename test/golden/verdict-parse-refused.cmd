verdict --stage parse ../../spec/02-lexical/05-hex-bad-digit.mod
