!> What one RESU occurrence of IMPR_RESU prints (doc/listings.md, "IMPR_RESU keywords"):
!> the mesh, the fields at their instants, the components, nodes and cells. Code_Aster's
!> keywords (U4.91.01, code_aster/Cata/Commands/impr_resu.py):
!>  RESULTAT   a result: NOM_CHAM (default, and TOUT_CHAM='OUI': every field the result has
!>             at each instant, result_access result_field_names) at TOUT_ORDRE / NUME_ORDRE
!>             / INST / LIST_INST (CRITERE, PRECISION; default every stored instant);
!>  CHAM_GD    one field (a CREA_CHAMP concept), without instant;
!>  MAILLAGE   the mesh (alone: the mesh only; with RESULTAT or CHAM_GD it must be theirs);
!>  NOM_CMP    the components, in that order, of every field that has them (a field with
!>             none of them is left out; none left is an error); default all (TOUT_CMP);
!>  GROUP_NO   the nodes printed, group after group, each once; GROUP_MA the cells printed,
!>             and with them their nodes for node fields; TOUT / neither: everything;
!>  IMPR_COOR, VALE_MAX, VALE_MIN, BORNE_INF, BORNE_SUP, SOUS_TITRE (format RESULTAT).
!> Fields are taken by result_access (stored, or made from the analysis's state the first
!> time), so a field IMPR_RESU prints is the one TEST_RESU tests.
module impr_resu_select
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: string_t, to_text, to_upper
    use deck_concept, only: concept_t
    use deck_command, only: keyword_set_t
    use mesh_types, only: mesh_t, find_node_group, nodes_of_group, find_cell_group, &
        cells_of_group
    use mesh_concept, only: mesh_concept_t
    use field_types, only: field_t, field_component, FIELD_NOEU
    use field_concept, only: field_concept_t
    use result_fields, only: result_fields_t
    use result_access, only: result_field_at, result_field_names, result_mesh
    use result_instants, only: selected_instants
    use field_support, only: mesh_of_support, model_of_support
    use model_types, only: model_t
    implicit none
    private

    !> One field at one instant.
    type, public :: print_item_t
        character(len=:), allocatable :: name     !< NOM_CHAM, or the CHAM_GD's name
        logical :: has_instant = .false.
        integer(i4) :: at = 0                     !< the stored instant (1..n_stored)
        integer(i4) :: nume_ordre = 0
        real(dp) :: inst = 0.0_dp
        type(field_t), pointer :: f => null()
    end type print_item_t

    !> What a RESU occurrence prints.
    type, public :: print_set_t
        type(mesh_t), pointer :: mesh => null()
        character(len=:), allocatable :: owner         !< result or field name; '' mesh only
        class(result_fields_t), pointer :: result => null()   !< RESULTAT, if given
        type(model_t), pointer :: model => null()      !< the elements, when known
        logical :: from_result = .false.
        logical :: mesh_only = .false.
        !> the fields, field by field, each at its instants in the order asked
        type(print_item_t), allocatable :: items(:)
        integer(i4) :: n_fields = 0                    !< distinct fields in items
        integer(i4) :: n_instants = 0                  !< instants per field
        type(string_t), allocatable :: components(:)   !< NOM_CMP, empty: all
        integer(i4), allocatable :: nodes(:)           !< the nodes printed, in order
        logical, allocatable :: node_taken(:)          !< (n_nodes)
        logical, allocatable :: cell_taken(:)          !< (n_cells)
        logical :: whole_mesh = .true.                 !< no GROUP_NO / GROUP_MA
        logical :: coordinates = .false.               !< IMPR_COOR
        logical :: vale_max = .false., vale_min = .false.
        logical :: has_lower = .false., has_upper = .false.
        real(dp) :: lower = 0.0_dp, upper = 0.0_dp     !< BORNE_INF, BORNE_SUP
        character(len=:), allocatable :: subtitle      !< SOUS_TITRE
    end type print_set_t

    public :: select_occurrence, item_has_components, locate

contains

    !> Resolves one RESU occurrence (module header).
    !>  st : located at the keyword at fault: a concept of another type, an instant not
    !>       stored, a field not computed, an unknown group, NOM_CMP that no field has,
    !>       MAILLAGE that is not the mesh of the result
    subroutine select_occurrence(occ, set, st)
        type(keyword_set_t), intent(in) :: occ
        type(print_set_t), intent(out) :: set
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        type(mesh_t), pointer :: given_mesh
        character(len=:), allocatable :: text
        given_mesh => null()
        set%owner = ''
        allocate (set%items(0), set%components(0))
        if (occ%has('MAILLAGE')) then
            call occ%get_concept('MAILLAGE', p, st)
            if (st%failed()) return
            select type (p)
            type is (mesh_concept_t)
                given_mesh => p%mesh
            class default
                call occ%error_at('MAILLAGE', 'expected a mesh (maillage), got ' // &
                    p%type_name(), st)
                return
            end select
        end if
        if (occ%has('RESULTAT')) then
            call result_items(occ, set, st)
        else if (occ%has('CHAM_GD')) then
            call field_items(occ, set, st)
        else if (associated(given_mesh)) then
            set%mesh => given_mesh
            set%mesh_only = .true.
        else
            call occ%error_at('RESULTAT', 'give RESULTAT, CHAM_GD or MAILLAGE', st, &
                STATUS_MODEL_ERROR)
        end if
        if (st%failed()) return
        if (associated(given_mesh) .and. .not. set%mesh_only) then
            if (.not. same_mesh(given_mesh, set%mesh)) then
                call occ%error_at('MAILLAGE', 'MAILLAGE is not the mesh of ' // set%owner // &
                    ' (' // to_text(given_mesh%n_nodes) // ' nodes and ' // &
                    to_text(given_mesh%n_cells) // ' cells against ' // &
                    to_text(set%mesh%n_nodes) // ' and ' // to_text(set%mesh%n_cells) // ')', &
                    st, STATUS_MODEL_ERROR)
                return
            end if
        end if
        if (set%mesh_only) return
        call select_components(occ, set, st)
        if (st%ok()) call select_topology(occ, set, st)
        if (st%failed()) return
        if (occ%has('IMPR_COOR')) then
            call occ%get_text('IMPR_COOR', text, st)
            set%coordinates = text == 'OUI'
        end if
        if (st%ok() .and. occ%has('VALE_MAX')) set%vale_max = .true.
        if (st%ok() .and. occ%has('VALE_MIN')) set%vale_min = .true.
        if (st%ok() .and. occ%has('BORNE_INF')) then
            set%has_lower = .true.
            call occ%get_real('BORNE_INF', set%lower, st)
        end if
        if (st%ok() .and. occ%has('BORNE_SUP')) then
            set%has_upper = .true.
            call occ%get_real('BORNE_SUP', set%upper, st)
        end if
        set%subtitle = ''
        if (st%ok() .and. occ%has('SOUS_TITRE')) call occ%get_text('SOUS_TITRE', &
            set%subtitle, st)
    end subroutine select_occurrence

    ! The same numbering: the same mesh concept, or one with as many nodes and cells.
    logical function same_mesh(a, b)
        type(mesh_t), pointer, intent(in) :: a, b
        same_mesh = associated(a, b)
        if (.not. same_mesh) same_mesh = a%n_nodes == b%n_nodes .and. a%n_cells == b%n_cells
    end function same_mesh

    ! RESULTAT: the fields NOM_CHAM (or every one) at the instants asked for.
    subroutine result_items(occ, set, st)
        type(keyword_set_t), intent(in) :: occ
        type(print_set_t), intent(inout) :: set
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        class(result_fields_t), pointer :: res
        type(string_t), allocatable :: names(:), here(:)
        integer, allocatable :: indices(:)
        logical :: by_inst, asked
        integer :: k, j, n, pass
        call occ%get_concept('RESULTAT', p, st)
        if (st%failed()) return
        select type (p)
        class is (result_fields_t)
            res => p
        class default
            call occ%error_at('RESULTAT', 'expected a result (evol_elas, evol_noli, ' // &
                'evol_ther), got ' // p%type_name(), st)
            return
        end select
        set%owner = res%name
        set%result => res
        set%from_result = .true.
        call model_of_support(p, set%model)
        call result_mesh(res, set%mesh, st)
        if (st%failed()) then
            st%message = st%message // ': IMPR_RESU prints on a mesh'
            call locate(occ, 'RESULTAT', st)
            return
        end if
        call selected_instants(occ, res, indices, by_inst, st)
        if (st%failed()) return
        asked = occ%has('NOM_CHAM')
        if (asked) then
            call occ%get_texts('NOM_CHAM', names, st)
            if (st%failed()) return
        else
            ! every field of every instant printed, in the order first met
            allocate (names(0))
            do k = 1, size(indices)
                here = result_field_names(res, int(indices(k), i4))
                do j = 1, size(here)
                    if (.not. any_name(names, here(j)%s)) call push(names, here(j)%s)
                end do
            end do
        end if
        if (.not. asked) call drop_unmade(res, indices, names)
        set%n_instants = size(indices, kind=i4)
        deallocate (set%items)
        allocate (set%items(size(names) * size(indices)))
        ! two passes: a field made from the analysis's state is stored in the result the
        ! first time, which may move the fields stored before it at that instant; the
        ! pointers are taken once every field is there
        do pass = 1, 2
            n = 0
            do j = 1, size(names)
                do k = 1, size(indices)
                    if (.not. asked) then
                        here = result_field_names(res, int(indices(k), i4))
                        if (.not. any_name(here, names(j)%s)) cycle   ! not at this instant
                    end if
                    n = n + 1
                    set%items(n)%name = to_upper(names(j)%s)
                    set%items(n)%has_instant = .true.
                    set%items(n)%at = int(indices(k), i4)
                    set%items(n)%nume_ordre = res%nume_ordre(indices(k))
                    set%items(n)%inst = res%inst(indices(k))
                    call result_field_at(res, int(indices(k), i4), names(j)%s, &
                        set%items(n)%f, st)
                    if (st%failed()) then
                        call locate(occ, trim(merge('NOM_CHAM', 'RESULTAT', asked)), st)
                        return
                    end if
                end do
            end do
        end do
        set%items = set%items(1:n)
        set%n_fields = size(names, kind=i4)
    end subroutine result_items

    ! Without NOM_CHAM: leaves out a field the analysis cannot make at one of the instants
    ! (a SIEF_ELGA of cells without material): every field that can be printed is.
    subroutine drop_unmade(res, indices, names)
        class(result_fields_t), intent(inout) :: res
        integer, intent(in) :: indices(:)
        type(string_t), allocatable, intent(inout) :: names(:)
        type(string_t), allocatable :: kept(:), here(:)
        type(field_t), pointer :: f
        type(status_t) :: st
        integer :: j, k
        logical :: made
        allocate (kept(0))
        do j = 1, size(names)
            made = .true.
            do k = 1, size(indices)
                here = result_field_names(res, int(indices(k), i4))
                if (.not. any_name(here, names(j)%s)) cycle
                call result_field_at(res, int(indices(k), i4), names(j)%s, f, st)
                if (st%failed()) made = .false.
            end do
            if (made) call push(kept, names(j)%s)
        end do
        call move_alloc(kept, names)
    end subroutine drop_unmade

    ! CHAM_GD: one field, on the mesh of its support.
    subroutine field_items(occ, set, st)
        type(keyword_set_t), intent(in) :: occ
        type(print_set_t), intent(inout) :: set
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        call occ%get_concept('CHAM_GD', p, st)
        if (st%failed()) return
        select type (p)
        type is (field_concept_t)
            call mesh_of_support(p%support, set%mesh, st)
            if (st%failed()) then
                call locate(occ, 'CHAM_GD', st)
                return
            end if
            set%owner = p%name
            call model_of_support(p%model, set%model)
            if (.not. associated(set%model)) call model_of_support(p%support, set%model)
            deallocate (set%items)
            allocate (set%items(1))
            set%items(1)%name = p%name
            set%items(1)%f => p%field
            set%n_fields = 1
            set%n_instants = 1
        class default
            call occ%error_at('CHAM_GD', 'expected a field (cham_no, cham_elem, carte), ' // &
                'got ' // p%type_name(), st)
        end select
    end subroutine field_items

    ! NOM_CMP: kept when some field has one of them; the fields with none are dropped.
    subroutine select_components(occ, set, st)
        type(keyword_set_t), intent(in) :: occ
        type(print_set_t), intent(inout) :: set
        type(status_t), intent(out) :: st
        type(print_item_t), allocatable :: kept(:)
        type(string_t), allocatable :: names(:)
        integer :: k, n
        if (.not. occ%has('NOM_CMP')) return
        call occ%get_texts('NOM_CMP', names, st)
        if (st%failed()) return
        do k = 1, size(names)
            names(k)%s = to_upper(names(k)%s)
        end do
        set%components = names
        allocate (kept(size(set%items)))
        n = 0
        do k = 1, size(set%items)
            if (.not. item_has_components(set%items(k), names)) cycle
            n = n + 1
            kept(n) = set%items(k)
        end do
        if (n == 0 .and. size(set%items) > 0) then
            call occ%error_at('NOM_CMP', 'no field printed has any of the components ' // &
                join(names) // ' (' // set%items(1)%name // ' has ' // &
                join(set%items(1)%f%components) // ')', st, STATUS_MODEL_ERROR)
            return
        end if
        set%items = kept(1:n)
    end subroutine select_components

    !> True when the field of `item` has one of `names` (or `names` is empty).
    logical function item_has_components(item, names)
        type(print_item_t), intent(in) :: item
        type(string_t), intent(in) :: names(:)
        integer :: k
        item_has_components = size(names) == 0
        do k = 1, size(names)
            if (field_component(item%f, names(k)%s) > 0) item_has_components = .true.
        end do
    end function item_has_components

    ! GROUP_NO / GROUP_MA (module header).
    subroutine select_topology(occ, set, st)
        type(keyword_set_t), intent(in) :: occ
        type(print_set_t), intent(inout) :: set
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: groups(:)
        integer(i4), allocatable :: members(:), order(:)
        integer(i4) :: k, g, m, n, c, p
        associate (mesh => set%mesh)
            allocate (set%node_taken(mesh%n_nodes), set%cell_taken(mesh%n_cells))
            set%whole_mesh = .not. (occ%has('GROUP_NO') .or. occ%has('GROUP_MA'))
            set%node_taken = set%whole_mesh
            set%cell_taken = set%whole_mesh .or. .not. occ%has('GROUP_MA')
            allocate (order(mesh%n_nodes))
            n = 0
            if (occ%has('GROUP_NO')) then
                call occ%get_texts('GROUP_NO', groups, st)
                if (st%failed()) return
                do k = 1, size(groups)
                    g = find_node_group(mesh, groups(k)%s, st)
                    if (st%failed()) then
                        call locate(occ, 'GROUP_NO', st)
                        return
                    end if
                    members = nodes_of_group(mesh, g)
                    do m = 1, size(members)
                        call take(members(m))
                    end do
                end do
            end if
            if (occ%has('GROUP_MA')) then
                call occ%get_texts('GROUP_MA', groups, st)
                if (st%failed()) return
                do k = 1, size(groups)
                    g = find_cell_group(mesh, groups(k)%s, st)
                    if (st%failed()) then
                        call locate(occ, 'GROUP_MA', st)
                        return
                    end if
                    members = cells_of_group(mesh, g)
                    do m = 1, size(members)
                        c = members(m)
                        set%cell_taken(c) = .true.
                        if (occ%has('GROUP_NO')) cycle     ! the nodes are GROUP_NO's
                        do p = mesh%cell_ptr(c), mesh%cell_ptr(c + 1) - 1
                            call take(mesh%cell_nodes(p))
                        end do
                    end do
                end do
            end if
            if (set%whole_mesh) then
                set%nodes = [(k, k = 1, mesh%n_nodes)]
            else
                set%nodes = order(1:n)
            end if
        end associate
    contains
        subroutine take(node)
            integer(i4), intent(in) :: node
            if (set%node_taken(node)) return
            set%node_taken(node) = .true.
            n = n + 1
            order(n) = node
        end subroutine take
    end subroutine select_topology

    !> Locates an error `st` at keyword `key` of the occurrence (its message and code kept).
    subroutine locate(occ, key, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: text
        integer :: code
        text = st%message
        code = st%code
        call occ%error_at(key, text, st, code)
    end subroutine locate

    pure logical function any_name(names, name)
        type(string_t), intent(in) :: names(:)
        character(len=*), intent(in) :: name
        integer :: k
        any_name = .false.
        do k = 1, size(names)
            if (to_upper(names(k)%s) == to_upper(name)) any_name = .true.
        end do
    end function any_name

    subroutine push(names, name)
        type(string_t), allocatable, intent(inout) :: names(:)
        character(len=*), intent(in) :: name
        type(string_t), allocatable :: bigger(:)
        integer :: n
        n = size(names)
        allocate (bigger(n + 1))
        bigger(1:n) = names
        bigger(n + 1)%s = name
        call move_alloc(bigger, names)
    end subroutine push

    pure function join(names) result(text)
        type(string_t), intent(in) :: names(:)
        character(len=:), allocatable :: text
        integer :: k
        text = ''
        do k = 1, size(names)
            if (k > 1) text = text // ' '
            text = text // names(k)%s
        end do
    end function join

end module impr_resu_select
