!> One entry point for every mesh format (LIRE_MAILLAGE FORMAT='ASTER' | 'GIBI' | 'GMSH' |
!> 'IDEAS' | 'MED').
module mesh_reader
    use status, only: status_t
    use strings, only: string_t, ends_with, to_lower, to_upper
    use mesh_types, only: mesh_t
    use mesh_aster_reader, only: read_aster_mesh
    use mesh_gmsh_reader, only: read_gmsh_mesh
    use mesh_med_reader, only: read_med_mesh
    use mesh_gibi_reader, only: read_gibi_mesh
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
    !>  format    : in, optional 'ASTER', 'GIBI', 'GMSH', 'IDEAS' or 'MED' (case-insensitive); without it the
    !>              extension decides: .msh is Gmsh, .med/.mmed/.rmed MED, anything else the
    !>              .mail format
    !>  mesh_name : in, optional, MED only: the mesh to read (NOM_MED; '' = the only one)
    !>  notes     : out, optional, lines for the .mess (MED: mesh read, groups dropped; GIBI:
    !>              nodes and cells left out; IDEAS: datasets skipped, group names cut)
    !>  colour_groups : in, optional, IDEAS only: CREA_GROUP_COUL='OUI' (default no)
    subroutine read_mesh(path, mesh, st, format, mesh_name, notes, colour_groups)
        character(len=*), intent(in) :: path
        type(mesh_t), intent(out) :: mesh
        type(status_t), intent(out) :: st
        character(len=*), intent(in), optional :: format, mesh_name
        type(string_t), allocatable, intent(out), optional :: notes(:)
        logical, intent(in), optional :: colour_groups
        character(len=:), allocatable :: kind, lower, name
        logical :: colours
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
        case ('GIBI')
            call read_gibi_mesh(path, mesh, st, lines)
        case ('IDEAS')
            colours = .false.
            if (present(colour_groups)) colours = colour_groups
            call read_ideas_mesh(path, colours, mesh, st, lines)
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
