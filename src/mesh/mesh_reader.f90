!> One entry point for every mesh format (LIRE_MAILLAGE FORMAT='ASTER' | 'GMSH' | 'MED' |
!> 'IDEAS').
module mesh_reader
    use status, only: status_t
    use strings, only: string_t, ends_with, to_lower, to_upper
    use mesh_types, only: mesh_t
    use mesh_aster_reader, only: read_aster_mesh
    use mesh_gmsh_reader, only: read_gmsh_mesh
    use mesh_med_reader, only: read_med_mesh
    use mesh_ideas_reader, only: read_ideas_mesh
    implicit none
    private
    public :: read_mesh
contains
    !> Reads the mesh in `path`.
    !>  path      : in, the file
    !>  mesh      : out, the mesh
    !>  st        : out, errors of the format's reader (text formats: file:line: message;
    !>              MED: "MED file PATH: ..." with st%keyword = 'NOM_MED' when the mesh name
    !>              is at fault)
    !>  format    : in, optional 'ASTER', 'GMSH', 'MED' or 'IDEAS' (case-insensitive);
    !>              without it the extension decides: .msh is Gmsh, .med/.mmed/.rmed MED,
    !>              anything else the .mail format
    !>  mesh_name : in, optional, MED only: the mesh to read (NOM_MED; '' = the only one)
    !>  notes     : out, optional, lines for the .mess (MED: mesh read, groups dropped)
    subroutine read_mesh(path, mesh, st, format, mesh_name, notes)
        character(len=*), intent(in) :: path
        type(mesh_t), intent(out) :: mesh
        type(status_t), intent(out) :: st
        character(len=*), intent(in), optional :: format, mesh_name
        type(string_t), allocatable, intent(out), optional :: notes(:)
        character(len=:), allocatable :: kind, lower, name
        type(string_t), allocatable :: lines(:)
        lower = to_lower(path)
        kind = 'ASTER'
        if (ends_with(lower, '.msh')) kind = 'GMSH'
        if (ends_with(lower, '.med') .or. ends_with(lower, '.mmed') .or. &
            ends_with(lower, '.rmed')) kind = 'MED'
        if (present(format)) kind = to_upper(format)
        allocate (lines(0))
        select case (kind)
        case ('GMSH')
            call read_gmsh_mesh(path, mesh, st)
        case ('IDEAS')
            call read_ideas_mesh(path, mesh, st)
        case ('MED')
            name = ''
            if (present(mesh_name)) name = mesh_name
            call read_med_mesh(path, mesh, st, mesh_name=name, notes=lines)
        case default
            call read_aster_mesh(path, mesh, st)
        end select
        if (present(notes)) call move_alloc(lines, notes)
    end subroutine read_mesh
end module mesh_reader
