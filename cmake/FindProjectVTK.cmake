# Debian's VTK: find_package(VTK) without components looks for the Qt5 module, so the component list is explicit,
# and it includes mpi because InteractionStyle pulls in ParallelMPI whose link interface names MPI::MPI_C.
set(RT_VTK_COMPONENTS
    CommonCore CommonDataModel CommonColor CommonTransforms CommonExecutionModel
    FiltersCore FiltersSources FiltersGeneral FiltersGeometry FiltersModeling FiltersExtraction
    RenderingCore RenderingOpenGL2 RenderingFreeType RenderingAnnotation RenderingUI
    RenderingContext2D RenderingContextOpenGL2 ChartsCore ViewsContext2D
    InteractionStyle InteractionWidgets IOImage IOExport IOExportGL2PS RenderingGL2PSOpenGL2 IOExportPDF mpi)
find_package(VTK 9.1 REQUIRED COMPONENTS ${RT_VTK_COMPONENTS})
