parse bom-no-newline.mod
