!> Command handler of the mesh layer: LIRE_MAILLAGE (doc/deck-language.md).
module mesh_commands
    use kinds, only: i4
    use status, only: status_t, STATUS_NOT_IMPLEMENTED, STATUS_IO_ERROR
    use strings, only: to_text
    use deck_concept, only: concept_t
    use deck_command, only: command_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_summary
    use mesh_reader, only: read_mesh
    use mesh_concept, only: mesh_concept_t
    use mesh_command_support, only: relocate_error
    implicit none
    private

    public :: run_lire_maillage

contains

    !> LIRE_MAILLAGE(FORMAT='ASTER'|'GMSH', UNITE=20): reads the mesh file bound to UNITE
    !> (ctx%unit_path) and writes its summary (nodes, cells per type, groups with sizes,
    !> bounding box) to the .mess.
    !>  result : out, a mesh_concept_t
    !>  st     : out, FORMAT='MED' (not supported yet) at FORMAT; an unbound unit or a
    !>           missing file at UNITE (naming the path and the --unit option); errors in
    !>           the mesh file keep their mesh-file location (file:line)
    subroutine run_lire_maillage(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(mesh_concept_t), allocatable :: mc
        character(len=:), allocatable :: format, path
        character(len=100), allocatable :: lines(:)
        integer(i4) :: unit, k
        logical :: exists
        call cmd%get_text('FORMAT', format, st)
        if (st%failed()) return
        if (format == 'MED') then
            call cmd%error_at('FORMAT', "MED meshes are not supported yet (convert the " // &
                "mesh to FORMAT='GMSH' (.msh) or FORMAT='ASTER' (.mail))", st, &
                code=STATUS_NOT_IMPLEMENTED)
            return
        end if
        call cmd%get_int('UNITE', unit, st)
        if (st%failed()) return
        call ctx%unit_path(unit, format, path, st)
        if (st%failed()) then
            call relocate_error(cmd, 'UNITE', st)
            return
        end if
        inquire (file=path, exist=exists)
        if (.not. exists) then
            call cmd%error_at('UNITE', 'mesh file ' // path // ' (unit ' // to_text(unit) // &
                ') does not exist (bind the unit to the mesh with --unit ' // to_text(unit) &
                // '=PATH)', st, code=STATUS_IO_ERROR)
            return
        end if
        allocate (mc)
        call read_mesh(path, mc%mesh, st, format)
        if (st%failed()) return
        lines = mesh_summary(mc%mesh)
        do k = 1, size(lines)
            call ctx%write_mess('    ' // trim(lines(k)))
        end do
        call move_alloc(mc, result)
    end subroutine run_lire_maillage

end module mesh_commands
