spec --impl 'sh spec-impl-store.sh {mode} {options} {files}' spec-impl-cases
