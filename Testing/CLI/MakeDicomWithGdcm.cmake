# cmake -DGDCMIMG=... -DDCMODIFY=... -DSLICES=dir -DOUT=dir -P MakeDicomWithGdcm.cmake
#
# Writes the CT test volume of TyndallCLICheck make-data (its stored slices,
# HU + 1024, int16 little endian, 32 x 28) as a DICOM series made by Debian's
# own tools instead of the tests' writer: GDCM's gdcmimg makes each file from
# the raw slice, dcmtk's dcmodify adds the patient geometry and the rescale
# tags. Files are named against their positions, as in ct-dicom.
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
foreach (k RANGE 11)
  math(EXPR name "11 - ${k}")
  math(EXPR z "10 + 2 * ${k}")
  set(dcm "${OUT}/im${name}.dcm")
  execute_process(
    COMMAND "${GDCMIMG}" -i "${SLICES}/slice${k}.raw" -o "${dcm}" --size 32,28 --depth 16
      --sign 1 -C 1.2.840.10008.5.1.4.1.1.2 -S 1.2.826.0.1.3680043.9.7433.9
    RESULT_VARIABLE result)
  if (NOT result EQUAL 0 OR NOT EXISTS "${dcm}")
    message(FATAL_ERROR "gdcmimg failed on slice ${k} (${result})")
  endif ()
  execute_process(
    COMMAND "${DCMODIFY}" -nb -i "(0020,0032)=-20\\-20\\${z}" -i "(0020,0037)=1\\0\\0\\0\\1\\0"
      -i "(0028,0030)=1.5\\1.25" -i "(0028,1052)=-1024" -i "(0028,1053)=1" -i "(0008,0060)=CT"
      -i "(0020,0013)=${name}" "${dcm}"
    RESULT_VARIABLE result)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "dcmodify failed on ${dcm} (${result})")
  endif ()
endforeach ()
message(STATUS "wrote 12 slices made by gdcmimg and dcmodify into ${OUT}")
