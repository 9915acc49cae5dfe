# Every text of ui/ has a finished German and Simplified Chinese translation (translations/*.ts). Run as
# `cmake -DLUPDATE=<lupdate> -DSOURCE_DIR=<the project> -DWORK_DIR=<a scratch folder> -P check_translations.cmake`.
# lupdate reads ui/'s sources into copies of the .ts files (the originals are never touched): a text new in the
# sources, or one whose translation is marked unfinished, comes out "unfinished"; the check fails naming each,
# with its context (the class that says it). `cmake --build . --target update_translations` brings such texts
# into the .ts files to be translated.
foreach(variable LUPDATE SOURCE_DIR WORK_DIR)
  if(NOT ${variable})
    message(FATAL_ERROR "${variable} is not set")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(languages de zh_CN)
set(copies)
foreach(language IN LISTS languages)
  file(COPY "${SOURCE_DIR}/translations/multidir_${language}.ts" DESTINATION "${WORK_DIR}")
  list(APPEND copies "${WORK_DIR}/multidir_${language}.ts")
endforeach()
# The include folders let lupdate resolve the namespaces of the classes (the contexts the .ts files use).
execute_process(
  COMMAND "${LUPDATE}" -silent -locations none -extensions cpp,h
          -I "${SOURCE_DIR}" -I "${SOURCE_DIR}/core/include" -I "${SOURCE_DIR}/hardware/include"
          -I "${SOURCE_DIR}/slicing/include" "${SOURCE_DIR}/ui" -ts ${copies}
  RESULT_VARIABLE status
  OUTPUT_VARIABLE output
  ERROR_VARIABLE output)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "lupdate failed (${status}):\n${output}")
endif()

set(missing 0)
foreach(language IN LISTS languages)
  file(READ "${WORK_DIR}/multidir_${language}.ts" ts)
  # CMake lists split at ';' and not inside brackets: the texts' own are set aside while the file is split.
  string(REPLACE ";" "@semicolon@" ts "${ts}")
  string(REPLACE "[" "@open@" ts "${ts}")
  string(REPLACE "]" "@close@" ts "${ts}")
  # One <context> at a time: its name, then each message of it whose translation is unfinished.
  string(REPLACE "</context>" "</context>;" contexts "${ts}")
  foreach(context IN LISTS contexts)
    if(NOT context MATCHES "<name>([^<]*)</name>")
      continue()
    endif()
    set(name "${CMAKE_MATCH_1}")
    string(REPLACE "</message>" "</message>;" messages "${context}")
    foreach(message IN LISTS messages)
      if(message MATCHES "type=\"unfinished\"" AND message MATCHES "<source>([^<]*)</source>")
        set(text "${CMAKE_MATCH_1}")
        string(REPLACE "@semicolon@" ";" text "${text}")
        string(REPLACE "@open@" "[" text "${text}")
        string(REPLACE "@close@" "]" text "${text}")
        message(SEND_ERROR "${language}: no finished translation of \"${text}\" (${name})")
        math(EXPR missing "${missing} + 1")
      endif()
    endforeach()
  endforeach()
endforeach()
if(missing GREATER 0)
  message(FATAL_ERROR "${missing} texts of ui/ have no finished translation: run the update_translations target "
                      "and translate them in translations/*.ts")
endif()
