list(APPEND TOONFACE_CORE_SOURCES
  detect/detector.h detect/detector.cpp
  detect/landmarkfigures.h detect/landmarkfigures.cpp
  detect/faceregions.h detect/faceregions.cpp
  detect/appearance.h detect/appearance.cpp
  detect/photocolours.h detect/photocolours.cpp
  detect/colourbalance.h detect/colourbalance.cpp
  detect/photopixels.h detect/photopixels.cpp detect/glassesfind.cpp detect/facialhairfind.cpp
  detect/headparse.h detect/headparse.cpp
  detect/haircolour.h detect/haircolour.cpp
  detect/hairoutline.h detect/hairoutline.cpp
  detect/headcover.h detect/headcover.cpp
  detect/skintone.h detect/skintone.cpp
  detect/appearanceevidence.h detect/appearanceevidence.cpp
  detect/appearancerating.cpp
  detect/agegroup.h detect/agegroup.cpp
  detect/levelface.h detect/levelface.cpp
  detect/browlook.h detect/browlook.cpp
  detect/hairsearch.h detect/hairsearch.cpp
  detect/labcolour.h detect/labcolour.cpp
  detect/headregions.h detect/headregions.cpp
  detect/landmarkmap.h detect/landmarkmap.cpp
  detect/landmarkfit.h
  detect/grayview.h
  detect/landmarkpredictor.h detect/landmarkpredictor.cpp
  detect/landmarkflat.h
  detect/shapemodelfile.h detect/shapemodelfile.cpp
  detect/cachefile.h detect/cachefile.cpp
  detect/facescan.h detect/facescan.cpp
  detect/modelcache.h detect/modelcache.cpp
  detect/detectionruntime.h detect/detectionruntime.cpp)
# dlib's detector and predictor are header templates: unoptimised they run ~40x slower, so
# these files are optimised even in Debug builds.
set_source_files_properties(detect/detector.cpp detect/landmarkpredictor.cpp detect/shapemodelfile.cpp detect/facescan.cpp detect/cachefile.cpp PROPERTIES COMPILE_OPTIONS "-O2")
list(APPEND TOONFACE_CORE_SOURCES
  detect/tsai.h detect/tsai.cpp
  detect/regions.h detect/regions.cpp
  detect/classic.h detect/classic.cpp
  detect/classicsteps.h detect/classiceyes.cpp detect/classicfeatures.cpp detect/classicpoints.cpp)
