!> One entry point for every mesh format (LIRE_MAILLAGE FORMAT='ASTER' | 'GMSH').
module mesh_reader
    use kinds, only: i4
    use status, only: status_t
    use strings, only: ends_with, to_lower, to_upper
    use mesh_types, only: mesh_t
    use mesh_aster_reader, only: read_aster_mesh
    use mesh_gmsh_reader, only: read_gmsh_mesh
    implicit none
    private
    public :: read_mesh
contains
    !> Reads the mesh in `path`.
    !>  path   : in, the file
    !>  mesh   : out, the mesh
    !>  st     : out, errors of the format's reader (file:line: message)
    !>  format : in, optional 'ASTER' or 'GMSH' (case-insensitive); without it the extension
    !>           decides: .msh is Gmsh, anything else is the .mail format
    subroutine read_mesh(path, mesh, st, format)
        character(len=*), intent(in) :: path
        type(mesh_t), intent(out) :: mesh
        type(status_t), intent(out) :: st
        character(len=*), intent(in), optional :: format
        logical :: gmsh
        gmsh = ends_with(to_lower(path), '.msh')
        if (present(format)) gmsh = to_upper(format) == 'GMSH'
        if (gmsh) then
            call read_gmsh_mesh(path, mesh, st)
        else
            call read_aster_mesh(path, mesh, st)
        end if
    end subroutine read_mesh
end module mesh_reader
