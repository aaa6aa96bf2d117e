# The files of the interactive page, web/page/ (names relative to it): staged by the wasm build
# beside the module, copied by the docs into the site. Sets IMPULSELAB_WEB_PAGE_FILES.
file(GLOB IMPULSELAB_WEB_PAGE_FILES CONFIGURE_DEPENDS RELATIVE "${CMAKE_CURRENT_LIST_DIR}/../page"
  "${CMAKE_CURRENT_LIST_DIR}/../page/*.html" "${CMAKE_CURRENT_LIST_DIR}/../page/*.css"
  "${CMAKE_CURRENT_LIST_DIR}/../page/*.js")
