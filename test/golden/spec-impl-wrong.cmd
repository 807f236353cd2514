spec --impl 'sh spec-impl-wrong.sh {mode} {options} {files}' --junit /dev/null spec-impl-cases
