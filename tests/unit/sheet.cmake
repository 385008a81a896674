rs_test(test_sheet unit SOURCES unit/test_sheet.c CASES closed_forms plane_strain bad_constants)
