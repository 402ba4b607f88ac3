!> POST_ELEM ENER_POT (U4.81.22): the elastic potential energy of a result's displacement,
!> 1/2 ue . Ke ue summed over the cells (parasol's element matrices: plates, with their
!> drilling stiffness COEF_RIGI_DRZ, plane solids and linear discretes), as Code_Aster's
!> peepot tabulates it: per stored instant (NUME_ORDRE, INST, or every one), per occurrence
!> TOUT (LIEU the mesh's name, ENTITE TOUT) and each GROUP_MA (ENTITE GROUP_MA): TOTALE and
!> POUR_CENT, its share of the whole model's energy in percent (100 for TOUT; 0 when the
!> whole has none). In a linear static analysis it is half the work of the loads
!> (Clapeyron), which the suite checks.
!> TRAV_EXT (pewext): per stored instant, NUME_ORDRE, INST, TRAV_ELAS = 1/2 FORC_NODA . DEPL
!> and TRAV_REEL, the work accumulated by the trapezoidal rule from the first instant
!> (0 there): W += 1/2 (F0.U1 - F1.U0 + F1.U1 - F0.U0); the dot products run over the
!> nodes and the components DX .. DRZ both fields hold.
!> Not built, each a located error: CHAM_GD (a displacement field without its result),
!> cells with a contact law (DIS_CHOC, DIS_CONTACT), results with thermal strains
!> (AFFE_VARC: Code_Aster counts the strain less its thermal part).
module post_elem_energy
    use kinds, only: dp, i4, i8
    use strings, only: string_t
    use status, only: status_t, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, find_cell_group, cells_of_group, cell_name
    use mesh_concept, only: mesh_concept_t
    use model_concept, only: model_concept_t
    use model_types, only: is_plate, is_plane_solid, is_discrete
    use model_dof_numbering, only: element_components, N_COMPONENTS, COMPONENT_NAMES
    use field_types, only: field_t, FIELD_NOEU, field_component
    use result_fields, only: result_fields_t
    use result_access, only: result_field_at
    use result_instants, only: selected_instants
    use analysis_result, only: result_concept_t
    use assembly_system, only: structure_t, cell_response, MAX_ELEMENT_DOFS
    use assembly_varc, only: has_thermal_load
    use element_fields, only: result_structure
    use table_concept, only: table_t, table_add_column, table_add_rows, table_set_int, &
        table_set_real, table_set_text, TABLE_INT, TABLE_REAL, TABLE_TEXT
    use table_keywords, only: relocate_at
    use crea_table_command, only: result_of_occurrence
    implicit none
    private
    public :: ener_pot_rows, trav_ext_rows, mesh_concept_name

contains

    !> The deck's name of the mesh concept `mesh` is (LIEU of TOUT rows), 'MAILLAGE' when
    !> no name holds it.
    function mesh_concept_name(ctx, mesh) result(name)
        type(run_context_t), intent(in) :: ctx
        type(mesh_t), pointer, intent(in) :: mesh
        character(len=:), allocatable :: name
        integer :: k
        name = 'MAILLAGE'
        do k = 1, ctx%nsymbol
            if (.not. associated(ctx%symbols(k)%value%obj)) cycle
            select type (q => ctx%symbols(k)%value%obj)
            type is (mesh_concept_t)
                if (associated(mesh, q%mesh)) name = ctx%symbols(k)%name
            end select
        end do
    end function mesh_concept_name

    !> The name of the mesh of the model concept named `model_name` ('MAILLAGE' unknown).
    function model_mesh_name(ctx, model_name) result(name)
        type(run_context_t), intent(in) :: ctx
        character(len=:), allocatable, intent(in) :: model_name
        character(len=:), allocatable :: name
        integer :: k
        name = 'MAILLAGE'
        if (.not. allocated(model_name)) return
        do k = 1, ctx%nsymbol
            if (ctx%symbols(k)%name /= model_name) cycle
            if (.not. associated(ctx%symbols(k)%value%obj)) cycle
            select type (q => ctx%symbols(k)%value%obj)
            type is (model_concept_t)
                name = mesh_concept_name(ctx, q%mesh)
            end select
        end do
    end function model_mesh_name

    !> ENER_POT: the columns and rows of the table (module header).
    subroutine ener_pot_rows(ctx, cmd, t, st)
        type(run_context_t), intent(in) :: ctx
        type(command_t), intent(in) :: cmd
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        class(result_fields_t), pointer :: res
        type(structure_t) :: s
        type(field_t), pointer :: f
        type(keyword_set_t) :: occ
        real(dp), allocatable :: energy(:)
        integer, allocatable :: indices(:)
        character(len=:), allocatable :: lieu
        logical :: by_inst
        integer :: j, k, c
        if (cmd%has('CHAM_GD') .or. .not. cmd%has('RESULTAT')) then
            call cmd%error_at('ENER_POT', 'ENER_POT reads the displacement of a result ' // &
                '(RESULTAT) in parasol; CHAM_GD is not built', st, STATUS_NOT_IMPLEMENTED)
            return
        end if
        call result_of_occurrence(cmd, res, st)
        if (st%failed()) return
        select type (res)
        type is (result_concept_t)
            call result_structure(res, s, st)
            if (st%ok()) call selected_instants(cmd, res, indices, by_inst, st)
            if (st%failed()) then
                call relocate_at(cmd, 'RESULTAT', st)
                return
            end if
            lieu = model_mesh_name(ctx, res%model_name)
        class default
            call cmd%error_at('RESULTAT', 'ENER_POT needs the result of an analysis ' // &
                '(MECA_STATIQUE, STAT_NON_LINE), which knows its model', st)
            return
        end select
        if (has_thermal_load(s)) then
            call cmd%error_at('RESULTAT', 'ENER_POT of a result with thermal strains ' // &
                '(AFFE_VARC) is not built by parasol', st, STATUS_NOT_IMPLEMENTED)
            return
        end if
        call table_add_column(t, 'NUME_ORDRE', TABLE_INT, c, st)
        call table_add_column(t, 'INST', TABLE_REAL, c, st)
        call table_add_column(t, 'LIEU', TABLE_TEXT, c, st, 24)
        call table_add_column(t, 'ENTITE', TABLE_TEXT, c, st, 8)
        call table_add_column(t, 'TOTALE', TABLE_REAL, c, st)
        call table_add_column(t, 'POUR_CENT', TABLE_REAL, c, st)
        if (st%failed()) return
        do j = 1, size(indices)
            call result_field_at(res, int(indices(j), i4), 'DEPL', f, st)
            if (st%failed()) then
                call relocate_at(cmd, 'RESULTAT', st)
                return
            end if
            call cell_energies(cmd, s, f, energy, st)
            if (st%failed()) return
            do k = 1, cmd%count('ENER_POT')
                occ = cmd%occurrence('ENER_POT', k)
                call occurrence_rows(occ, s%mesh, lieu, res%nume_ordre(indices(j)), &
                    res%inst(indices(j)), energy, t, st)
                if (st%failed()) return
            end do
        end do
    end subroutine ener_pot_rows

    !> TRAV_EXT: the columns and rows of the table (module header).
    subroutine trav_ext_rows(cmd, t, st)
        type(command_t), intent(in) :: cmd
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        class(result_fields_t), pointer :: res
        type(field_t), pointer :: u, f
        real(dp), allocatable :: u0(:, :), f0(:, :), u1(:, :), f1(:, :)
        integer, allocatable :: indices(:)
        logical :: by_inst
        real(dp) :: w
        integer :: j, c, r
        call result_of_occurrence(cmd, res, st)
        if (st%ok()) call selected_instants(cmd, res, indices, by_inst, st)
        if (st%failed()) then
            call relocate_at(cmd, 'RESULTAT', st)
            return
        end if
        call table_add_column(t, 'NUME_ORDRE', TABLE_INT, c, st)
        call table_add_column(t, 'INST', TABLE_REAL, c, st)
        call table_add_column(t, 'TRAV_ELAS', TABLE_REAL, c, st)
        call table_add_column(t, 'TRAV_REEL', TABLE_REAL, c, st)
        w = 0.0_dp
        do j = 1, size(indices)
            if (st%failed()) return
            call result_field_at(res, int(indices(j), i4), 'DEPL', u, st)
            if (st%ok()) call result_field_at(res, int(indices(j), i4), 'FORC_NODA', f, st)
            if (st%failed()) then
                call relocate_at(cmd, 'RESULTAT', st)
                return
            end if
            call displacement_part(u, u1)
            call displacement_part(f, f1)
            if (j >= 2) w = w + 0.5_dp * (sum(f0 * u1) - sum(f1 * u0) + sum(f1 * u1) - &
                                          sum(f0 * u0))
            call table_add_rows(t, 1)
            r = t%n_rows
            call table_set_int(t, 1, r, int(res%nume_ordre(indices(j)), i8), st)
            call table_set_real(t, 2, r, res%inst(indices(j)), st)
            call table_set_real(t, 3, r, 0.5_dp * sum(f1 * u1), st)
            call table_set_real(t, 4, r, w, st)
            call move_alloc(u1, u0)
            call move_alloc(f1, f0)
        end do
    end subroutine trav_ext_rows

    !> The DX .. DRZ components of a nodal field, 0 where it holds none (cnsreddepl).
    subroutine displacement_part(f, v)
        type(field_t), intent(in) :: f
        real(dp), allocatable, intent(out) :: v(:, :)
        integer :: comp, k, node
        allocate (v(N_COMPONENTS, f%n_nodes), source=0.0_dp)
        if (f%location /= FIELD_NOEU) return
        do comp = 1, N_COMPONENTS
            k = field_component(f, trim(COMPONENT_NAMES(comp)))
            if (k == 0) cycle
            do node = 1, f%n_nodes
                if (f%node_has(k, node)) v(comp, node) = f%node_values(k, node)
            end do
        end do
    end subroutine displacement_part

    !> 1/2 ue . Ke ue of every cell (0 for cells without an element or energy).
    subroutine cell_energies(cmd, s, f, energy, st)
        type(command_t), intent(in) :: cmd
        type(structure_t), intent(in) :: s
        type(field_t), intent(in) :: f
        real(dp), allocatable, intent(out) :: energy(:)
        type(status_t), intent(inout) :: st
        real(dp) :: ue(MAX_ELEMENT_DOFS), fn
        real(dp), allocatable :: ke(:, :), fe(:), un(:)
        logical :: mask(N_COMPONENTS), closed
        integer(i4) :: c, p, comp, n, kind, k
        type(status_t) :: cst
        allocate (energy(s%mesh%n_cells), source=0.0_dp)
        if (f%location /= FIELD_NOEU) return
        do c = 1, s%mesh%n_cells
            kind = s%model%element(c)
            if (.not. (is_plate(kind) .or. is_plane_solid(kind) .or. is_discrete(kind))) cycle
            if (allocated(s%choc)) then
                if (s%choc(c)) then
                    call cmd%error_at('ENER_POT', 'cell ' // cell_name(s%mesh, c) // &
                        ' has a contact law (DIS_CHOC / DIS_CONTACT): its potential ' // &
                        'energy is not built by parasol', st, STATUS_NOT_IMPLEMENTED)
                    return
                end if
            end if
            mask = element_components(kind)
            n = 0
            do p = s%mesh%cell_ptr(c), s%mesh%cell_ptr(c + 1) - 1
                do comp = 1, N_COMPONENTS
                    if (.not. mask(comp)) cycle
                    n = n + 1
                    ue(n) = 0.0_dp
                    k = field_component(f, trim(COMPONENT_NAMES(comp)))
                    if (k == 0) cycle
                    if (f%node_has(k, s%mesh%cell_nodes(p))) &
                        ue(n) = f%node_values(k, s%mesh%cell_nodes(p))
                end do
            end do
            if (n == 0) cycle
            if (allocated(ke)) deallocate (ke, fe)
            allocate (ke(n, n), fe(n))
            un = ue(1:n)
            call cell_response(s, c, un, n, .true., .false., ke, fe, closed, fn, cst)
            if (cst%failed()) then
                call cmd%error_at('RESULTAT', cst%message, st, cst%code)
                return
            end if
            energy(c) = 0.5_dp * dot_product(un, fe)
        end do
    end subroutine cell_energies

    !> The rows of one ENER_POT occurrence at one instant.
    subroutine occurrence_rows(occ, mesh, lieu, nume_ordre, inst, energy, t, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: lieu
        integer(i4), intent(in) :: nume_ordre
        real(dp), intent(in) :: inst
        real(dp), intent(in) :: energy(:)
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        type(string_t), allocatable :: names(:)
        real(dp) :: total
        integer(i4) :: g
        integer :: k
        total = sum(energy)
        if (occ%has('TOUT')) call add_row(lieu, 'TOUT', total)
        if (occ%has('GROUP_MA')) then
            call occ%get_texts('GROUP_MA', names, st)
            if (st%failed()) return
            do k = 1, size(names)
                g = find_cell_group(mesh, names(k)%s, st)
                if (st%failed()) then
                    call relocate_at(occ, 'GROUP_MA', st)
                    return
                end if
                call add_row(names(k)%s, 'GROUP_MA', sum(energy(cells_of_group(mesh, g))))
            end do
        end if
    contains
        subroutine add_row(where, entite, value)
            character(len=*), intent(in) :: where, entite
            real(dp), intent(in) :: value
            integer :: r
            if (st%failed()) return
            call table_add_rows(t, 1)
            r = t%n_rows
            call table_set_int(t, 1, r, int(nume_ordre, i8), st)
            call table_set_real(t, 2, r, inst, st)
            call table_set_text(t, 3, r, where, st)
            call table_set_text(t, 4, r, entite, st)
            call table_set_real(t, 5, r, value, st)
            if (abs(total) > 0.0_dp) then
                call table_set_real(t, 6, r, 100.0_dp * value / total, st)
            else
                call table_set_real(t, 6, r, 0.0_dp, st)
            end if
        end subroutine add_row
    end subroutine occurrence_rows

end module post_elem_energy
