!> Materials (DEFI_MATERIAU) and their assignment to cells (AFFE_MATERIAU).
!>
!> A material holds every behaviour the deck gives it, as data (behaviour_t: the keyword
!> values of one factor keyword of DEFI_MATERIAU, numbers, texts or concepts such as
!> functions), and the two behaviours parasol's elements use, decoded: ELAS (E, NU, RHO
!> optional) and DIS_CONTACT (the unilateral spring data of DIS_CHOC). Optional values
!> carry presence flags; defaults are Code_Aster's (RIGI_TAN = DIST_1 = DIST_2 = COULOMB
!> = 0). A command that needs a behaviour parasol does not build stops, naming it
!> (check_materials, doc/deck-language.md "Materials as data").
!> Function values are POINTERS to concepts owned by the run context: a material never
!> owns or frees them and must not outlive the run.
module model_material
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: to_text, string_t
    use function_concept, only: function_concept_t
    use mesh_types, only: mesh_t, cell_label
    use model_types, only: model_t, is_plate, is_plane_solid, ELEMENT_NAMES
    use model_varc, only: varc_field_t, varc_init
    implicit none
    private

    !> Kinds of a behaviour's keyword value.
    integer(i4), parameter, public :: VALUE_NUMBERS = 1, VALUE_TEXTS = 2, VALUE_FUNCTIONS = 3

    !> A reference to a function concept owned by the run context. (Only functions: a
    !> pointer to the base concept type here would make the material concept's type
    !> recursive, whose automatic deallocation gfortran 12 gets wrong: valgrind found the
    !> AFFE_MATERIAU mesh copy lost.)
    type, public :: function_pointer_t
        class(function_concept_t), pointer :: ptr => null()
    end type function_pointer_t

    !> One keyword of a behaviour and its value(s): numbers (integers as reals), texts
    !> (other concepts, e.g. tables, by their deck names) or functions.
    type, public :: material_value_t
        character(len=:), allocatable :: key
        integer(i4) :: kind = VALUE_NUMBERS
        real(dp), allocatable :: numbers(:)
        type(string_t), allocatable :: texts(:)
        type(function_pointer_t), allocatable :: functions(:)
    end type material_value_t

    !> One behaviour of a material (a factor keyword of DEFI_MATERIAU: ELAS_ORTH, THER,
    !> ECRO_LINE, ...) with the values the deck gave and the catalog's defaults.
    type, public :: behaviour_t
        character(len=:), allocatable :: name
        type(material_value_t), allocatable :: values(:)
    end type behaviour_t

    !> ELAS behaviour (isotropic linear elasticity).
    type, public :: elas_t
        real(dp) :: e = 0.0_dp          !< Young's modulus
        real(dp) :: nu = 0.0_dp         !< Poisson's ratio
        logical :: has_rho = .false.
        real(dp) :: rho = 0.0_dp        !< density, if has_rho
    end type elas_t

    !> DIS_CONTACT behaviour (DIS_CHOC springs). Code_Aster defaults in the initialisers.
    type, public :: dis_contact_t
        logical :: has_rigi_nor = .false.
        real(dp) :: rigi_nor = 0.0_dp   !< normal stiffness; absent: the discrete's own
        real(dp) :: rigi_tan = 0.0_dp   !< tangential stiffness
        real(dp) :: dist_1 = 0.0_dp     !< gap reduction at node 1
        real(dp) :: dist_2 = 0.0_dp     !< gap reduction at node 2
        logical :: has_jeu = .false.
        real(dp) :: jeu = 0.0_dp        !< gap (POI1 discretes), if has_jeu
        real(dp) :: coulomb = 0.0_dp    !< friction coefficient
        real(dp) :: amor_nor = 0.0_dp   !< normal damping (accepted; statics ignore it)
        real(dp) :: amor_tan = 0.0_dp   !< tangential damping (accepted; statics ignore it)
    end type dis_contact_t

    !> One material (a DEFI_MATERIAU result).
    type, public :: material_t
        character(len=:), allocatable :: name   !< deck name, for messages
        !> every behaviour given, ELAS and DIS_CONTACT included (may be unallocated: none)
        type(behaviour_t), allocatable :: behaviours(:)
        logical :: has_elas = .false.
        type(elas_t) :: elas
        logical :: has_dis_contact = .false.
        type(dis_contact_t) :: dis_contact
    end type material_t

    !> Materials assigned to cells (an AFFE_MATERIAU result): cell_material(c) indexes
    !> materials(:), 0 = none.
    type, public :: material_field_t
        type(material_t), allocatable :: materials(:)
        integer(i4), allocatable :: cell_material(:)
        type(varc_field_t) :: varc          !< AFFE_VARC (model_varc, elem's)
    end type material_field_t

    public :: material_field_init, assign_material, check_materials, material_of_cell, &
        add_behaviour, has_behaviour, behaviour_index, behaviour_number, behaviour_function, &
        behaviour_names, elastic_behaviour

    !> The elastic behaviours of Code_Aster's DEFI_MATERIAU (one per material, its EXCLUS
    !> rule): the ones parasol's plate and plane elements do not build are named when a
    !> cell that needs elasticity has one of them instead of ELAS.
    character(len=15), parameter :: ELASTIC_BEHAVIOURS(16) = [character(len=15) :: 'ELAS', &
        'ELAS_FO', 'ELAS_VISCO', 'ELAS_FLUI', 'ELAS_ISTR', 'ELAS_ISTR_FO', &
        'ELAS_VISCO_ISTR', 'ELAS_ORTH', 'ELAS_ORTH_FO', 'ELAS_VISCO_ORTH', 'ELAS_COQUE', &
        'ELAS_COQUE_FO', 'ELAS_HYPER', 'ELAS_HYPER_VISC', 'ELAS_GLRC', 'ELAS_DHRC']

contains

    !> An empty material field over the cells of `mesh`.
    subroutine material_field_init(field, mesh)
        type(material_field_t), intent(out) :: field
        type(mesh_t), intent(in) :: mesh
        allocate (field%materials(0))
        allocate (field%cell_material(mesh%n_cells), source=0_i4)
        call varc_init(field%varc, mesh%n_cells)
    end subroutine material_field_init

    !> Assigns `material` to `cells` (later assignments override earlier ones). The material
    !> is copied into the field once per call.
    subroutine assign_material(field, cells, material)
        type(material_field_t), intent(inout) :: field
        integer(i4), intent(in) :: cells(:)
        type(material_t), intent(in) :: material
        field%materials = [field%materials, material]
        field%cell_material(cells) = size(field%materials, kind=i4)
    end subroutine assign_material

    !> Index in field%materials of the material of cell c (0 if none).
    integer(i4) function material_of_cell(field, c)
        type(material_field_t), intent(in) :: field
        integer(i4), intent(in) :: c
        material_of_cell = field%cell_material(c)
    end function material_of_cell

    !> Checks every modelled cell has the data its element needs: plates and plane solids
    !> need ELAS with E > 0 and -1 < NU < 0.5 (plates also take ELAS_FO, ELAS_COQUE,
    !> ELAS_COQUE_FO and DEFI_COMPOSITE laminates, model_plate_section; ELAS_ORTH straight
    !> on a plate is refused; plane solids take ELAS_ORTH, assembly_plane_law); discretes
    !> and load edges need nothing (ELAS on springs is
    !> accepted and unused, as in Code_Aster).
    !>  st : out, STATUS_MODEL_ERROR naming the first cell (and its group) that lacks data;
    !>       STATUS_NOT_IMPLEMENTED when its material gives another elastic behaviour
    !>       (ELAS_ORTH, ELAS_COQUE, ...) that parasol's element does not build, naming it
    subroutine check_materials(field, model, mesh, st)
        type(material_field_t), intent(in) :: field
        type(model_t), intent(in) :: model
        type(mesh_t), intent(in) :: mesh
        type(status_t), intent(out) :: st
        integer(i4) :: c, m
        character(len=:), allocatable :: other
        do c = 1, model%n_cells
            if (.not. (is_plate(model%element(c)) .or. is_plane_solid(model%element(c)))) cycle
            m = field%cell_material(c)
            if (m == 0) then
                call set_error(st, STATUS_MODEL_ERROR, cell_label(mesh, c) // ' (' // &
                    trim(ELEMENT_NAMES(model%element(c))) // ') has no material: ' // &
                    'AFFE_MATERIAU must give it one with ELAS')
                return
            end if
            associate (mat => field%materials(m))
                if (is_plate(model%element(c)) .and. plate_elasticity(mat)) cycle
                ! ELAS_ORTH on a plane solid: its law in the MASSIF frame (assembly_plane_law)
                if (is_plane_solid(model%element(c)) .and. .not. mat%has_elas .and. &
                    elastic_behaviour(mat) == 'ELAS_ORTH') cycle
                ! ELAS_FO on a plane solid: E and NU of its functions (assembly_plane_law)
                if (is_plane_solid(model%element(c)) .and. .not. mat%has_elas .and. &
                    elastic_behaviour(mat) == 'ELAS_FO') cycle
                if (is_plate(model%element(c)) .and. has_behaviour(mat, 'ELAS_ORTH')) then
                    call set_error(st, STATUS_MODEL_ERROR, 'material ' // label(mat) // &
                        ' on ' // cell_label(mesh, c) // ' gives ELAS_ORTH to a DKT plate:' &
                        // ' Code_Aster refuses it (ELEMENTS_91); give the layers through ' &
                        // 'DEFI_COMPOSITE')
                    return
                end if
                if (.not. mat%has_elas) then
                    other = elastic_behaviour(mat)
                    if (len(other) > 0) then
                        call set_error(st, STATUS_NOT_IMPLEMENTED, 'material ' // label(mat) &
                            // ' on ' // cell_label(mesh, c) // ' gives ' // other // ', ' // &
                            'which parasol''s ' // trim(ELEMENT_NAMES(model%element(c))) // &
                            ' element does not build yet (it takes ELAS: E, NU)')
                        return
                    end if
                    call set_error(st, STATUS_MODEL_ERROR, 'material ' // label(mat) // ' on ' &
                        // cell_label(mesh, c) // ' has no ELAS: its ' // &
                        trim(ELEMENT_NAMES(model%element(c))) // ' element needs E and NU')
                    return
                end if
                if (mat%elas%e <= 0.0_dp .or. mat%elas%nu <= -1.0_dp .or. &
                    mat%elas%nu >= 0.5_dp) then
                    call set_error(st, STATUS_MODEL_ERROR, 'material ' // label(mat) // ' on ' &
                        // cell_label(mesh, c) // ': ELAS needs E > 0 and -1 < NU < 0.5 (E = ' &
                        // to_text(mat%elas%e) // ', NU = ' // to_text(mat%elas%nu) // ')')
                    return
                end if
            end associate
        end do
    end subroutine check_materials

    !> True when the material gives a plate's elasticity other than ELAS, which
    !> model_plate_section decodes: ELAS_FO, ELAS_COQUE, ELAS_COQUE_FO, a DEFI_COMPOSITE
    !> laminate (ELAS_COQMU).
    pure logical function plate_elasticity(mat)
        type(material_t), intent(in) :: mat
        plate_elasticity = has_behaviour(mat, 'ELAS_FO') .or. &
            has_behaviour(mat, 'ELAS_COQUE') .or. has_behaviour(mat, 'ELAS_COQUE_FO') .or. &
            has_behaviour(mat, 'ELAS_COQMU')
    end function plate_elasticity

    !> The elastic behaviour of a material other than ELAS (ELAS_ORTH, ELAS_FO, ...), ''
    !> when it has none.
    function elastic_behaviour(mat) result(name)
        type(material_t), intent(in) :: mat
        character(len=:), allocatable :: name
        integer :: k
        name = ''
        do k = 2, size(ELASTIC_BEHAVIOURS)
            if (has_behaviour(mat, trim(ELASTIC_BEHAVIOURS(k)))) then
                name = trim(ELASTIC_BEHAVIOURS(k))
                return
            end if
        end do
    end function elastic_behaviour

    !> Appends a behaviour to a material (the caller checks it is not there yet).
    subroutine add_behaviour(mat, behaviour)
        type(material_t), intent(inout) :: mat
        type(behaviour_t), intent(in) :: behaviour
        if (.not. allocated(mat%behaviours)) allocate (mat%behaviours(0))
        mat%behaviours = [mat%behaviours, behaviour]
    end subroutine add_behaviour

    !> Index of behaviour `name` in mat%behaviours, 0 when the material does not give it.
    pure integer function behaviour_index(mat, name)
        type(material_t), intent(in) :: mat
        character(len=*), intent(in) :: name
        integer :: k
        behaviour_index = 0
        if (.not. allocated(mat%behaviours)) return
        do k = 1, size(mat%behaviours)
            if (mat%behaviours(k)%name == name) then
                behaviour_index = k
                return
            end if
        end do
    end function behaviour_index

    !> True when the material gives behaviour `name` (ELAS_ORTH, THER, ...).
    pure logical function has_behaviour(mat, name)
        type(material_t), intent(in) :: mat
        character(len=*), intent(in) :: name
        has_behaviour = behaviour_index(mat, name) > 0
    end function has_behaviour

    !> The names of the material's behaviours, blank-separated ('ELAS THER').
    function behaviour_names(mat) result(text)
        type(material_t), intent(in) :: mat
        character(len=:), allocatable :: text
        integer :: k
        text = ''
        if (.not. allocated(mat%behaviours)) return
        do k = 1, size(mat%behaviours)
            if (k > 1) text = text // ' '
            text = text // mat%behaviours(k)%name
        end do
    end function behaviour_names

    !> The number given to keyword `key` of behaviour `behaviour` (its first value).
    !>  found : out, .false. when the material lacks the behaviour or the keyword, or the
    !>          keyword holds no number (then x = 0)
    subroutine behaviour_number(mat, behaviour, key, x, found)
        type(material_t), intent(in) :: mat
        character(len=*), intent(in) :: behaviour, key
        real(dp), intent(out) :: x
        logical, intent(out) :: found
        integer :: b, k
        x = 0.0_dp
        found = .false.
        b = behaviour_index(mat, behaviour)
        if (b == 0) return
        k = value_index(mat%behaviours(b), key)
        if (k == 0) return
        associate (v => mat%behaviours(b)%values(k))
            if (v%kind /= VALUE_NUMBERS) return      ! (no short-circuit: two tests)
            if (.not. allocated(v%numbers)) return
            if (size(v%numbers) == 0) return
            x = v%numbers(1)
            found = .true.
        end associate
    end subroutine behaviour_number

    !> The function given to keyword `key` of behaviour `behaviour` (ELAS_FO E, ...): a
    !> pointer to a concept owned by the run context; null when the material lacks it or
    !> the value is not a function.
    function behaviour_function(mat, behaviour, key) result(f)
        type(material_t), intent(in) :: mat
        character(len=*), intent(in) :: behaviour, key
        class(function_concept_t), pointer :: f
        integer :: b, k
        f => null()
        b = behaviour_index(mat, behaviour)
        if (b == 0) return
        k = value_index(mat%behaviours(b), key)
        if (k == 0) return
        associate (v => mat%behaviours(b)%values(k))
            if (v%kind /= VALUE_FUNCTIONS .or. size(v%functions) == 0) return
            f => v%functions(1)%ptr
        end associate
    end function behaviour_function

    ! Index of keyword `key` in a behaviour, 0 if absent.
    pure integer function value_index(behaviour, key)
        type(behaviour_t), intent(in) :: behaviour
        character(len=*), intent(in) :: key
        integer :: k
        value_index = 0
        if (.not. allocated(behaviour%values)) return
        do k = 1, size(behaviour%values)
            if (behaviour%values(k)%key == key) then
                value_index = k
                return
            end if
        end do
    end function value_index

    pure function label(mat) result(text)
        type(material_t), intent(in) :: mat
        character(len=:), allocatable :: text
        text = '(unnamed)'
        if (allocated(mat%name)) text = mat%name
    end function label

end module model_material
