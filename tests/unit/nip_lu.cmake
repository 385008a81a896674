rs_test(test_nip_lu unit SOURCES unit/test_nip_lu.c CASES against_dgetrs transposed_against_dgetrs)
