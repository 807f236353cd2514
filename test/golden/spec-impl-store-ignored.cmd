spec --impl 'sh spec-impl-store.sh {mode} {options} {files}' --ignore store spec-impl-cases
