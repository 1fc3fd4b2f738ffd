# The bad-input matrix: "name|file|message". The files are written by
# `TyndallCLICheck make-bad-inputs` (TyndallBadInputs.cxx); the message is a
# part of what tyndall-render prints after "tyndall-render: <path>: ".
# Documentation/bad-inputs.md describes every row (a test checks that the
# two agree).
set(tyndall_bad_inputs
  # MetaImage
  "mhd-huge|mhd-huge.mhd|100000 x 100000 x 100000 points of 1 x unsigned char, 1e+15 bytes (909 TiB), above the memory limit of 4096 MiB"
  "mhd-truncated|mhd-truncated.mhd|truncated: the header claims 262144 bytes (256 KiB) of voxel data of"
  "mhd-truncated-float|mhd-truncated-float.mhd|truncated: the header claims 16384 bytes (16 KiB) of voxel data"
  "mha-truncated|mha-truncated.mha|truncated: the header claims 4096 bytes (4 KiB) of voxel data after byte 168"
  "mhd-bad-zlib|mhd-bad-zlib.mhd|is corrupted (zlib: incorrect header check)"
  "mhd-zero-dim|mhd-zero-dim.mhd|the image is 0 x 16 x 16 points"
  "mhd-negative-dim|mhd-negative-dim.mhd|the image is 16 x -16 x 16 points"
  "mhd-zero-spacing|mhd-zero-spacing.mhd|the spacing (1, 0, 1) is not finite and non-zero along every axis"
  "mhd-nan-spacing|mhd-nan-spacing.mhd|MetaImage cannot parse file"
  "mhd-inf-origin|mhd-inf-origin.mhd|MetaImage cannot parse file"
  "mhd-unknown-type|mhd-unknown-type.mhd|Unknown data type: 28"
  "mhd-zero-channels|mhd-zero-channels.mhd|the header claims 0 components per voxel"
  "mhd-empty|mhd-empty.mhd|not a MetaImage file"
  "mhd-no-data-file|mhd-no-data-file.mhd|MetaImage cannot parse file"
  # NRRD
  "nrrd-truncated|nrrd-truncated.nrrd|truncated: the header claims 4096 bytes (4 KiB) of voxel data after byte 96"
  "nhdr-truncated|nhdr-truncated.nhdr|nhdr-truncated.raw', which holds 3000 bytes"
  "nhdr-missing-data|nhdr-missing-data.nhdr|no-such-data.raw' named by the header does not exist"
  "nrrd-huge|nrrd-huge.nrrd|above the memory limit of 4096 MiB"
  "nrrd-zero-size|nrrd-zero-size.nrrd|impossible NRRD sizes '16 0 16'"
  "nrrd-zero-spacing|nrrd-zero-spacing.nrrd|the spacing (1, 1, 0) is not finite and non-zero"
  "nrrd-nan-spacing|nrrd-nan-spacing.nrrd|the spacing (1, nan, 1) is not finite and non-zero"
  "nrrd-unknown-type|nrrd-unknown-type.nrrd|unknown NRRD type 'quaternion'"
  "nrrd-bzip2|nrrd-bzip2.nrrd|Unsupported encoding: bzip2"
  "nrrd-bad-gzip|nrrd-bad-gzip.nrrd|is corrupted (zlib: incorrect header check)"
  "nrrd-time|nrrd-time.nrrd|Time in NRRD array not supported"
  "nrrd-garbage|nrrd-garbage.nrrd|not a NRRD file"
  # NIfTI
  "nii-truncated|nii-truncated.nii|truncated: the header claims 30720 bytes (30 KiB) of voxel data after byte 352"
  "nii-header-only|nii-header-only.nii|not a NIfTI file"
  "nii-huge|nii-huge.nii|30000 x 30000 x 30000 points of 1 x float"
  "nii-zero-dim|nii-zero-dim.nii|the image is 24 x 0 x 16 points"
  "nii-zero-spacing|nii-zero-spacing.nii|the spacing (pixdim) (1, 0, 1.5) is not finite and non-zero"
  "nii-nan-spacing|nii-nan-spacing.nii|the spacing (pixdim) (nan, 1, 1.5) is not finite and non-zero"
  "nii-unknown-type|nii-unknown-type.nii|unknown NIfTI datatype code 1234"
  "nii-bad-rank|nii-bad-rank.nii|impossible NIfTI header: 9 dimensions"
  "niigz-truncated|niigz-truncated.nii.gz|NIFTI file is truncated"
  "niigz-garbage|niigz-garbage.nii.gz|not a NIfTI file"
  # Legacy VTK
  "vtk-truncated-ascii|vtk-truncated-ascii.vtk|the data is shorter than the header declares (Error reading ascii data"
  "vtk-truncated-binary|vtk-truncated-binary.vtk|the data is shorter than the header declares (Error reading binary data"
  "vtk-huge|vtk-huge.vtk|above the memory limit of 4096 MiB"
  "vtk-zero-spacing|vtk-zero-spacing.vtk|the spacing (1, 0, 1) is not finite and non-zero"
  "vtk-unknown-type|vtk-unknown-type.vtk|Unsupported data type: quaternion"
  "vtk-garbage|vtk-garbage.vtk|not a legacy VTK data file"
  # VTK XML image data
  "vti-huge|vti-huge.vti|100000 x 100000 x 100000 points of 1 x float"
  "vti-nan-spacing|vti-nan-spacing.vti|the spacing \"1 nan 1\" is not finite and non-zero"
  "vti-zero-spacing|vti-zero-spacing.vti|the spacing \"0 1 1\" is not finite and non-zero"
  "vti-unknown-type|vti-unknown-type.vti|Unknown data type \"Quaternion\""
  "vti-short-ascii|vti-short-ascii.vti|Error reading extent 0 15 0 15 0 15 from piece 0"
  "vti-appended-truncated|vti-appended-truncated.vti|truncated: the appended data of array 'blob' runs past the end of the file"
  "vti-garbage|vti-garbage.vti|not a VTK XML file"
  # DICOM series
  "dicom-truncated|dicom-truncated|slice2.dcm: truncated: its 32 x 28 pixels of 16 bits x 1 need 1792 bytes of pixel data, the file holds 266"
  "dicom-mixed-sizes|dicom-mixed-sizes|the slices differ: slice0.dcm has 32 x 28 pixels of 16 bits x 1, slice3.dcm has 64 x 64"
  "dicom-huge|dicom-huge|slice0.dcm: truncated: its 65535 x 65535 pixels"
  "dicom-zero-spacing|dicom-zero-spacing|the spacing (0, 0, 2) is not finite and non-zero"
  # SLC, OpenVDB (the VDB reader's own matrix is TestOpenVDBReaderBadFiles)
  "slc-garbage|slc-garbage.slc|not a SLC file"
  "vdb-truncated|vdb-truncated.vdb|truncated or corrupted file: grid \"density\" claims bytes")
