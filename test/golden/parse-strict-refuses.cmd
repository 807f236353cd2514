parse --strict bom-no-newline.mod
